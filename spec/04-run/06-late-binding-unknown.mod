MODULE late_binding_unknown
! @format 3
! @section 4.6
! @section 12
! @expect ok
! @description A late-bound name that denotes no procedure raises ERR_REFUNKPRC (chapter 12: unknown procedure at run time, late binding) at the call.
! @output before
! @exit 1
! @error ERR_REFUNKPRC 16:5
  PROC proc1()
    TPWrite "proc1";
  ENDPROC
  PROC main()
    VAR string name := "proc9";
    TPWrite "before";
    % name %;
    TPWrite "after";
  ENDPROC
ENDMODULE

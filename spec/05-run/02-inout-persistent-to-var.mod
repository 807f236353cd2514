MODULE inout_persistent_to_var
! @format 3
! @section 5.2
! @section 12
! @expect ok
! @description Section 5.2's table, cell "parameter inout pers" to a var parameter: an execution error. The inout parameter is bound to a persistent, so passing it on to a var parameter raises ERR_ARGNOTVAR (chapter 12) at that call.
! @output in mid
! @exit 1
! @error ERR_ARGNOTVAR 16:5
  PERS num p := 1;
  PROC need_var(VAR num y)
    TPWrite "wrong";
  ENDPROC
  PROC mid(INOUT num x)
    TPWrite "in mid";
    need_var x;
  ENDPROC
  PROC main()
    mid p;
  ENDPROC
ENDMODULE

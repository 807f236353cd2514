MODULE absent_parameter_used
! @format 3
! @section 5.2
! @section 12
! @expect ok
! @description The value of an absent optional parameter cannot be used (section 5.2): reading it raises ERR_NOTPRES (chapter 12) at the statement that reads it.
! @output start
! @exit 1
! @error ERR_NOTPRES 13:5
  PROC show(\num n)
    VAR num x;
    TPWrite "start";
    x := n + 1;
    TPWrite "wrong";
  ENDPROC
  PROC main()
    show;
  ENDPROC
ENDMODULE

MODULE inout_variable_to_pers
! @format 3
! @section 5.2
! @section 12
! @expect ok
! @description Section 5.2's table, cell "parameter inout var" to a pers parameter: an execution error. The inout parameter is bound to a variable, so passing it on to a pers parameter raises ERR_ARGNOTPER (chapter 12) at that call.
! @output in mid
! @exit 1
! @error ERR_ARGNOTPER 16:5
  VAR num v := 1;
  PROC need_pers(PERS num y)
    TPWrite "wrong";
  ENDPROC
  PROC mid(INOUT num x)
    TPWrite "in mid";
    need_pers x;
  ENDPROC
  PROC main()
    mid v;
  ENDPROC
ENDMODULE

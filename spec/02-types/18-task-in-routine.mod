MODULE task_in_routine
! @format 2
! @section 2.18
! @expect semantic-error 7:5
! @description The TASK directive can only be used at module level, not inside a routine; refused at TASK.
  FUNC num f()
    TASK VAR num b;
    RETURN 1;
  ENDFUNC
ENDMODULE

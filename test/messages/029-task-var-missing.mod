MODULE t
! @expect-message 3:8: syntax error: expected VAR or PERS after TASK: TASK declares a task-global variable or persistent (§2.18); found the identifier num
  TASK num shared;
ENDMODULE

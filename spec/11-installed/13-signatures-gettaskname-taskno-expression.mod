MODULE sig_gettaskname_taskno
! @format 2
! @section 5.2
! @section 13
! @expect semantic-error 11:25
! @description GetTaskName (\TaskNo) stores the task number: its argument must be a variable, an expression is refused.
  VAR num n;
  VAR string name;
  PROC main()
    name := GetTaskName(\TaskNo:=n);
    name := GetTaskName(\TaskNo:=n + 1);
  ENDPROC
ENDMODULE

MODULE name_b
! @task T_ARC
  PROC main()
    VAR num n;
    VAR num m;
    VAR string me;
    me := GetTaskName(\TaskNo := n);
    TPWrite me + " " + NumToStr(n, 0) + " motion " + GetTaskName(\MecTaskNo := m) + " " + NumToStr(m, 0);
  ENDPROC
ENDMODULE

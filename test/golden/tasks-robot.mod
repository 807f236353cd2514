MODULE tasks_robot
  ! The motion task of the check --task and run --task goldens.
  CONST num n := 3;
  PERS num counts{n} := [0, 0, 0];
  PERS bool ready := FALSE;
  PERS string state := "idle";
  VAR syncident meet;
  PERS tasks both{2} := [["T_ROB1"], ["T_B"]];
  PROC main()
    WaitUntil ready;
    counts{1} := 1;
    WaitSyncTask meet, both;
    TPWrite "robot: " + state;
  ENDPROC
ENDMODULE

MODULE tasks_move
  ! The motion task of run-tasks-samples: one joint move of 1 s.
  CONST jointtarget there := [[30, 0, 0, 0, 30, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  PROC main()
    MoveAbsJ there, v100 \T := 1, fine, tool0;
    TPWrite "moved";
  ENDPROC
ENDMODULE

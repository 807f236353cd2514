MODULE tasks_cell_types
  ! A second task that declares the shared persistents of tasks-robot.mod with other types,
  ! each refused at its declaration (ch. 14, R-14-c), and one that agrees.
  PERS num counts{4};
  PERS num ready;
  PERS STRING state;
  PROC main()
  ENDPROC
ENDMODULE

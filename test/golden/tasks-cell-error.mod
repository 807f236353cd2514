MODULE tasks_cell_error
  ! A second task with an error of its own: the buffers are not judged together then.
  PERS num ready;
  PROC main()
    ready := "yes";
  ENDPROC
ENDMODULE

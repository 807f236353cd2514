MODULE tasks_cell_wait
  ! A task without a robot that waits half a second.
  PROC main()
    WaitTime 0.5;
    TPWrite "cell waited";
  ENDPROC
ENDMODULE

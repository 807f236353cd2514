MODULE tasks_stop_early
  ! A task that an error stops at once, while the other task of the run waits on.
  VAR num divisor := 0;
  PROC main()
    divisor := 1 / divisor;
  ENDPROC
ENDMODULE

MODULE tasks_wait_on
  ! A task whose wait nothing ends before the --max-time limit.
  PROC main()
    WaitTime 10;
    TPWrite "never";
  ENDPROC
ENDMODULE

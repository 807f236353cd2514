MODULE deadlock_b
! @task T_B
  PERS bool lock;
  PROC main()
    TPWrite "B waits";
    WaitTestAndSet lock;
    TPWrite "not reached";
  ENDPROC
ENDMODULE

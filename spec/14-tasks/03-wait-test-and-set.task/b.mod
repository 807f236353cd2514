MODULE mutex_b
! @task T_B
  PERS bool lock;
  PROC main()
    WaitTime 0.5;
    TPWrite "B TestAndSet " \Bool := TestAndSet(lock);
    WaitTestAndSet lock;
    TPWrite "B holds";
    lock := FALSE;
  ENDPROC
ENDMODULE

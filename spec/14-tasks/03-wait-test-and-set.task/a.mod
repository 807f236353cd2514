MODULE mutex_a
! @format 4
! @task T_ROB1
! @section 14
! @expect ok
! @description WaitTestAndSet and TestAndSet on a system-global persistent give mutual exclusion between tasks: B's TestAndSet fails while A holds the lock, B's WaitTestAndSet waits until A releases it.
! @output A holds
! @output B TestAndSet FALSE
! @output A releases
! @output B holds
  PERS bool lock := FALSE;
  PROC main()
    WaitTestAndSet lock;
    TPWrite "A holds";
    WaitTime 1;
    TPWrite "A releases";
    lock := FALSE;
  ENDPROC
ENDMODULE

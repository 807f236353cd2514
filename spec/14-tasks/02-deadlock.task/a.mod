MODULE deadlock_a
! @format 4
! @task T_ROB1
! @section 14
! @expect ok
! @exit 3
! @description Both tasks wait for a semaphore that neither releases (WaitTestAndSet on a set system-global persistent): nothing can end the waits, a deadlock (exit status 3).
! @output A waits
! @output B waits
  PERS bool lock := TRUE;
  PROC main()
    TPWrite "A waits";
    WaitTestAndSet lock;
    TPWrite "not reached";
  ENDPROC
ENDMODULE

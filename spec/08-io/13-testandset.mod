MODULE testandset_case
! @format 3
! @section 13
! @expect ok
! @statement-time 0
! @description TestAndSet takes a free semaphore (TRUE, and sets it) and refuses a taken one (FALSE); WaitTestAndSet waits until the semaphore is free, then takes it: here a trap frees it at 0.5 s.
! @output first TRUE
! @output second FALSE
! @output taken at 500 TRUE
  VAR bool sem := FALSE;
  VAR intnum t;
  VAR clock c;
  TRAP release
    sem := FALSE;
  ENDTRAP
  PROC main()
    TPWrite "first " \Bool:=TestAndSet(sem);
    TPWrite "second " \Bool:=TestAndSet(sem);
    ClkStart c;
    CONNECT t WITH release;
    ITimer \Single, 0.5, t;
    WaitTestAndSet sem;
    TPWrite "taken at " + NumToStr(Round(ClkRead(c) * 1000), 0) + " " + ValToStr(sem);
  ENDPROC
ENDMODULE

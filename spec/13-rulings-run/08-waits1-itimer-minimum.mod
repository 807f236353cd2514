MODULE itimer_minimum
! @format 3
! @section 8
! @section 13
! @expect ok
! @statement-time 0
! @description ITimer's Time below the minimum is raised to it (installed-facts.md section 6, doc/rulings.md R-8-waits1): 0.1 s for a cyclic timer, so that ITimer 1E-9 interrupts ten times during WaitTime 1, and 0.01 s with \Single or \SingleSafe; a time of zero is ERR_ARGVALERR (08-interrupts/08-order-errors).
! @output cyclic: 10 interrupts in 1 s
! @output cyclic 0.05: 10 interrupts in 1 s
! @output single at 10 ms
! @output safe at 10 ms
! @output single 0.5 at 500 ms
  VAR intnum t;
  VAR clock c;
  VAR num n;
  VAR num at;
  TRAP count
    n := n + 1;
    at := ClkRead(c);
  ENDTRAP
  PROC main()
    CONNECT t WITH count;
    ClkStart c;
    ITimer 1E-9, t;
    WaitTime 1;
    IDelete t;
    TPWrite "cyclic: " + ValToStr(n) + " interrupts in 1 s";
    n := 0;
    CONNECT t WITH count;
    ITimer 0.05, t;
    WaitTime 1;
    IDelete t;
    TPWrite "cyclic 0.05: " + ValToStr(n) + " interrupts in 1 s";
    CONNECT t WITH count;
    ClkReset c;
    ClkStart c;
    ITimer \Single, 1E-9, t;
    WaitTime 1;
    TPWrite "single at " + ValToStr(Round(at * 1000)) + " ms";
    ClkReset c;
    ClkStart c;
    ITimer \SingleSafe, 0.001, t;
    WaitTime 1;
    TPWrite "safe at " + ValToStr(Round(at * 1000)) + " ms";
    ClkReset c;
    ClkStart c;
    ITimer \Single, 0.5, t;
    WaitTime 1;
    TPWrite "single 0.5 at " + ValToStr(Round(at * 1000)) + " ms";
  ENDPROC
ENDMODULE

MODULE backtrap
  ! Interrupts while a BACKWARD handler runs (doc/rulings.md R-6-w): the timer's traps are
  ! served during its WaitTime and run forward; the second raises an error, which no handler
  ! handles, not even the trap's own (§6.1, R-6-c).
  VAR intnum t;
  VAR num n := 0;
  TRAP tick
    n := n + 1;
    TPWrite "tick " \Num:=n;
    IF n = 2 RAISE 5;
  ERROR
    TPWrite "the trap's handler";
    RETURN;
  ENDTRAP
  PROC Slow()
    TPWrite "slow forward";
  BACKWARD
    TPWrite "slow backward";
    WaitTime 0.25;
    TPWrite "slow backward done";
  ENDPROC
  PROC main()
    CONNECT t WITH tick;
    ITimer 0.1, t;
    Slow;
    IDelete t;
  ERROR (5)
    TPWrite "main's recovery point";
  ENDPROC
ENDMODULE

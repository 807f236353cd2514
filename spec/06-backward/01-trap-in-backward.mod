MODULE trap_in_backward
! @format 3
! @section 6.1
! @section 8
! @expect ok
! @description Interrupts while a BACKWARD handler runs (doc/rulings.md R-6-w): run forward, Slow ends before the timer's first interrupt; run backward (test/golden/debug-back-trap.cmd), Slow's BACKWARD handler waits 0.25 s, the timer's traps are served meanwhile and run forward, and the second one's error is handled by no handler, not the trap's own nor main's recovery point (section 6.1).
! @exit 0
! @output slow forward
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

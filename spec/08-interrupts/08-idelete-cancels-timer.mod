MODULE idelete_cancels_timer
! @format 3
! @section 8
! @expect ok
! @statement-time 0
! @description IDelete clears the interrupt condition (chapter 8): a cyclic timer deleted at 0.5 s does not fire at 1 s, even though the same variable gets the same number again and a new 1 s timer, which fires at 1.5 s only.
! @output n=1
! @output same number TRUE
  VAR intnum i1;
  VAR num first;
  VAR num n := 0;
  TRAP t
    n := n + 1;
  ENDTRAP
  PROC main()
    CONNECT i1 WITH t;
    first := i1;
    ITimer 1, i1;
    WaitTime 0.5;
    IDelete i1;
    CONNECT i1 WITH t;
    ITimer 1, i1;
    WaitTime 1.2;
    TPWrite "n=" \Num:=n;
    TPWrite "same number " \Bool:=(i1 = first);
  ENDPROC
ENDMODULE

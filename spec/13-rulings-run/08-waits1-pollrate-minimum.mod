MODULE pollrate_minimum
! @format 3
! @section 13
! @expect ok
! @statement-time 0
! @description WaitUntil \PollRate below the minimum polls at the minimum, 0.04 s (installed-facts.md section 4, doc/rulings.md R-8-waits1): a condition that holds at its fifth evaluation ends the wait at 0.16 s, whether the rate asked is 1E-30 s or 0.04 s; a rate of 0.5 s is kept; zero is ERR_ARGVALERR.
! @output 1E-30: 5 polls, 160 ms
! @output 0.04: 5 polls, 160 ms
! @output 0.5: 5 polls, 2000 ms
! @output 0: ERR_ARGVALERR
  VAR clock c;
  VAR num polls;
  VAR string label;
  FUNC bool fifth()
    polls := polls + 1;
    RETURN polls >= 5;
  ENDFUNC
  PROC measure(string what, num r)
    polls := 0;
    label := what;
    ClkReset c;
    ClkStart c;
    WaitUntil fifth() \PollRate:=r;
    TPWrite what + ": " + ValToStr(polls) + " polls, " + ValToStr(Round(ClkRead(c) * 1000)) + " ms";
  ENDPROC
  PROC main()
    measure "1E-30", 1E-30;
    measure "0.04", 0.04;
    measure "0.5", 0.5;
    measure "0", 0;
  ERROR
    IF ERRNO = ERR_ARGVALERR TPWrite label + ": ERR_ARGVALERR";
    TRYNEXT;
  ENDPROC
ENDMODULE

MODULE long_jump_between_retry
! @format 3
! @section 7.2
! @section 8
! @expect ok
! @statement-time 0.1
! @description A long jump from a trap arrives at main between two statements: the trap was served at the entry of the third TPWrite (chapter 8), so no statement of main is in progress. main's ERROR (34) handles the error, and RETRY goes on where the program pointer was, at that entry: the third TPWrite runs once (doc/rulings.md R-7.2-m).
! @output one
! @output two
! @output recovered 34
! @output three
! @output four
  VAR intnum t;
  TRAP failing
    RAISE 34;
  ENDTRAP
  PROC main()
    CONNECT t WITH failing;
    ITimer \Single, 0.25, t;
    TPWrite "one";
    TPWrite "two";
    TPWrite "three";
    TPWrite "four";
  ERROR (34)
    TPWrite "recovered " \Num:=ERRNO;
    RETRY;
  ENDPROC
ENDMODULE

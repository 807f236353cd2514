MODULE long_jump_between_trynext
! @format 3
! @section 7.2
! @section 8
! @expect ok
! @statement-time 0.1
! @description A routine called by a trap raises error 34 and has no error handler: the search for an error recovery point goes from it up the chain, through the trap, to main, which the trap interrupted at the entry of its third TPWrite (section 7.2, chapter 8). The long jump abandons the routine (its UNDO handler runs) and the trap; main's handler ends with TRYNEXT, which goes on where the program pointer was, at that entry: the third TPWrite is not skipped, no statement having caused the error (doc/rulings.md R-7.2-m).
! @output one
! @output two
! @output undo of fail_deep
! @output trynext 34
! @output three
! @output four
  VAR intnum t;
  TRAP failing
    fail_deep;
    TPWrite "not reached";
  ENDTRAP
  PROC fail_deep()
    RAISE 34;
  UNDO
    TPWrite "undo of fail_deep";
  ENDPROC
  PROC main()
    CONNECT t WITH failing;
    ITimer \Single, 0.25, t;
    TPWrite "one";
    TPWrite "two";
    TPWrite "three";
    TPWrite "four";
  ERROR (34)
    TPWrite "trynext " \Num:=ERRNO;
    TRYNEXT;
  ENDPROC
ENDMODULE

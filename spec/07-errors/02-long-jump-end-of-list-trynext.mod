MODULE long_jump_end_of_list
! @format 3
! @section 7.2
! @section 8
! @expect ok
! @statement-time 0.1
! @description The end of a statement list is a point of response (chapter 8): work's last statement, IEnable, lets in the interrupt that occurred while interrupts were disabled, and its trap is served after it, at the end of work's body. The trap's error 34 is carried by a long jump to work's ERROR (34), no statement of work being in progress; TRYNEXT goes on from there, the end of the body, and work returns (doc/rulings.md R-7.2-m).
! @output waited
! @output trynext 34
! @output back in main
  VAR intnum t;
  TRAP failing
    RAISE 34;
  ENDTRAP
  PROC work()
    CONNECT t WITH failing;
    IDisable;
    ITimer \Single, 0.05, t;
    WaitTime 0.1;
    TPWrite "waited";
    IEnable;
  ERROR (34)
    TPWrite "trynext " \Num:=ERRNO;
    TRYNEXT;
  ENDPROC
  PROC main()
    work;
    TPWrite "back in main";
  ENDPROC
ENDMODULE

MODULE long_jump_from_trap
! @format 3
! @section 8
! @section 7.2
! @expect ok
! @statement-time 0
! @description A long jump carries an error from trap level to an error recovery point at normal level (section 7.2): the trap's error 33 abandons the trap and the routine it interrupted (whose UNDO handler runs), and main's ERROR (33) handles it at normal level, where interrupts are served again.
! @output undo of work
! @output recovered 33
! @output tick after recovery
  VAR intnum t;
  VAR intnum t2;
  TRAP failing
    RAISE 33;
  ENDTRAP
  TRAP tick
    TPWrite "tick after recovery";
  ENDTRAP
  PROC work()
    WaitTime 5;
    TPWrite "not reached";
  UNDO
    TPWrite "undo of work";
  ENDPROC
  PROC main()
    CONNECT t WITH failing;
    ITimer \Single, 0.5, t;
    work;
    TPWrite "not reached";
  ERROR (33)
    TPWrite "recovered " \Num:=ERRNO;
    CONNECT t2 WITH tick;
    ITimer \Single, 0.1, t2;
    WaitTime 1;
    RETURN;
  ENDPROC
ENDMODULE

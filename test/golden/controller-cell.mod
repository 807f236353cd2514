MODULE cell
  ! Waits for parts on an input, counts them in a trap on the input's rising edge, keeps a
  ! timer, queues the interrupts that come during a handshake (IDisable) and while a trap
  ! runs, and ends in a long jump from the emergency-stop trap to main's recovery point, which
  ! abandons clamp (its UNDO handler releases the clamp).
  VAR intnum part_int;
  VAR intnum tick_int;
  VAR intnum stop_int;
  VAR num parts := 0;
  VAR num ticks := 0;
  TRAP on_part
    parts := parts + 1;
    TPWrite "part " \Num:=parts;
    WaitTime 0.05;
  ENDTRAP
  TRAP on_tick
    ticks := ticks + 1;
  ENDTRAP
  TRAP on_stop
    TPWrite "emergency stop after ticks " \Num:=ticks;
    RAISE 40;
  ENDTRAP
  PROC clamp()
    SetDO do_clamp, 1;
    WaitTime 0.3;
    Reset do_clamp;
  UNDO
    TPWrite "undo: release the clamp";
    Reset do_clamp;
  ENDPROC
  PROC main()
    CONNECT part_int WITH on_part;
    ISignalDI di_part, 1, part_int;
    CONNECT tick_int WITH on_tick;
    ITimer 1, tick_int;
    CONNECT stop_int WITH on_stop;
    ISignalDI \Single, di_stop, 1, stop_int;
    WHILE TRUE DO
      WaitDI di_part, 1;
      ! The handshake with the conveyor is not interrupted: a part arriving meanwhile waits.
      IDisable;
      WaitTime 0.2;
      IEnable;
      clamp;
      WaitTime 0.5;
    ENDWHILE
  ERROR (40)
    TPWrite "recovered: parts " \Num:=parts;
    TPWrite "clamp " \Num:=do_clamp;
    RETURN;
  ENDPROC
ENDMODULE

MODULE triggint_stopmove_clearpath
! @format 3
! @section 13
! @section 8
! @expect ok
! @statement-time 0
! @io io/trigg.io
! @description The triggers follow the robot (R-4.1-trigg6). A TriggInt 250 mm before the end of a 500 mm move at v100 interrupts at 2.5 s; its trap stops the robot for 3 s (StopMove, WaitTime, StartMove), so the TriggIO 0.5 s before the end point (\Time), due at 4.5 s while the robot stands, acts at 7.5 s, and the move ends at 8 s. When the trap clears the path instead (ClearPath), the robot stays where it was stopped (y = 0) and the trigger it never gets to is dropped: do_gun does not change. An interrupt that sleeps (ISleep) when the robot gets there is discarded; TriggInt activates it again (R-4.1-trigg3).
! @output position at 2500
! @output do_gun 1 at 7500
! @output end 8000
! @output position at 2500
! @output cleared: do_gun 0 y 0
! @output asleep: no trap
! @output position at 2500
  CONST robtarget p1 := [[300,-250,300],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p2 := [[300,250,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR clock clk;
  VAR intnum gun_changed;
  VAR intnum halfway;
  VAR triggdata gun_on;
  VAR triggdata middle;
  VAR num mode := 0;
  TRAP gun
    TPWrite "do_gun " + NumToStr(do_gun, 0) + " at " + NumToStr(1000 * ClkRead(clk), 0);
  ENDTRAP
  TRAP position
    TPWrite "position at " + NumToStr(1000 * ClkRead(clk), 0);
    StopMove;
    IF mode = 0 THEN
      WaitTime 3;
    ELSE
      ClearPath;
    ENDIF
    StartMove;
  ENDTRAP
  PROC main()
    VAR robtarget here;
    MoveJ p1, v1000, fine, tool0;
    CONNECT gun_changed WITH gun;
    ISignalDO do_gun, 2, gun_changed;
    CONNECT halfway WITH position;
    TriggIO gun_on, 0.5 \Time \DOp:=do_gun, 1;
    TriggInt middle, 250, halfway;
    ClkStart clk;
    TriggL p2, v100, gun_on \T2:=middle, fine, tool0;
    TPWrite "end " \Num:=Round(1000 * ClkRead(clk));
    ! The path cleared in the trap.
    mode := 1;
    IDelete gun_changed;
    Reset do_gun;
    MoveJ p1, v1000, fine, tool0;
    ClkReset clk;
    ClkStart clk;
    TriggL p2, v100, gun_on \T2:=middle, fine, tool0;
    WaitTime 5;
    here := CRobT(\Tool:=tool0);
    TPWrite "cleared: do_gun " + NumToStr(do_gun, 0) + " y " + NumToStr(Abs(here.trans.y), 0);
    ! The interrupt asleep, then activated again by TriggInt.
    mode := 0;
    MoveJ p1, v1000, fine, tool0;
    ISleep halfway;
    TriggL p2, v100, middle, fine, tool0;
    TPWrite "asleep: no trap";
    MoveJ p1, v1000, fine, tool0;
    TriggInt middle, 250, halfway;
    ClkReset clk;
    ClkStart clk;
    TriggL p2, v100, middle, fine, tool0;
  ENDPROC
ENDMODULE

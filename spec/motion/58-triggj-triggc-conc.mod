MODULE triggj_triggc_conc
! @format 3
! @section 13
! @expect ok
! @statement-time 0
! @io io/trigg.io
! @description TriggC moves as MoveC: a half circle of radius 100 at v100 takes pi s, and its triggers are at arc lengths, 100 mm from the start point (1 s) and 100 mm before the end point (pi - 1 s). TriggJ moves as MoveJ: 50 mm at v10, where the TCP's chord sets the time (T-joint, 5 s), its distances measured on the chord (R-4.1-trigg1): 10 mm from the start point at 1 s, 10 mm before the end point at 4 s. TriggL \Conc lets the program go on at once, and its trigger still acts at its position (50 mm from the start at v100: 0.5 s) while the program waits.
! @output do_gun 1 at 1000
! @output do_gun 0 at 2142
! @output TriggC end 3142
! @output do_gun 1 at 1000
! @output do_gun 0 at 4000
! @output TriggJ end 5000
! @output left at 0
! @output do_gun 1 at 500
! @output in position at 1000
  CONST robtarget c0 := [[400,-100,300],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget cir := [[500,0,300],[0,0,1,0],[0,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget c1 := [[400,100,300],[0,0,1,0],[0,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR clock clk;
  VAR intnum gun_changed;
  VAR triggdata on100;
  VAR triggdata off100;
  VAR triggdata on10;
  VAR triggdata off10;
  VAR triggdata on50;
  TRAP gun
    TPWrite "do_gun " + NumToStr(do_gun, 0) + " at " + NumToStr(1000 * ClkRead(clk), 0);
  ENDTRAP
  PROC main()
    MoveJ c0, v1000, fine, tool0;
    CONNECT gun_changed WITH gun;
    ISignalDO do_gun, 2, gun_changed;
    TriggIO on100, 100 \Start \DOp:=do_gun, 1;
    TriggIO off100, 100 \DOp:=do_gun, 0;
    TriggIO on10, 10 \Start \DOp:=do_gun, 1;
    TriggIO off10, 10 \DOp:=do_gun, 0;
    TriggIO on50, 50 \Start \DOp:=do_gun, 1;
    ClkStart clk;
    TriggC cir, c1, v100, on100 \T2:=off100, fine, tool0;
    TPWrite "TriggC end " \Num:=Round(1000 * ClkRead(clk));
    ClkReset clk;
    ClkStart clk;
    TriggJ Offs(c1, 0, -50, 0), v10, on10 \T2:=off10, fine, tool0;
    TPWrite "TriggJ end " \Num:=Round(1000 * ClkRead(clk));
    Reset do_gun;
    ClkReset clk;
    ClkStart clk;
    TriggL \Conc, Offs(c1, 0, -50, 100), v100, on50, fine, tool0;
    TPWrite "left at " \Num:=Round(1000 * ClkRead(clk));
    WaitRob \InPos;
    TPWrite "in position at " \Num:=Round(1000 * ClkRead(clk));
  ENDPROC
ENDMODULE

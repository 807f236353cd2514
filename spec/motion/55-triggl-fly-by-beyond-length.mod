MODULE triggl_fly_by_beyond_length
! @format 3
! @section 13
! @expect ok
! @statement-time 0
! @io io/trigg.io
! @description A trigger acts on every Trigg move that names it (R-4.1-trigg2): gun_on, 50 mm from the start point, on the 500 mm move at v100 (0.5 s) and on the 200 mm move after it (5 s + 0.5 s). The end point of a fly-by move is its programmed point on the segment's time law (R-4.1-trigg1): with z10 the corner runs from 4.9 s to 5.1 s and gun_off, at 0 mm from the end point, acts at 5 s, where MoveLDO sets its output. A distance beyond the move's length is its start point (600 mm before the end of a 200 mm move: 5 s) or, with \Start, its end point (7 s).
! @output do_gun 1 at 500
! @output do_gun 0 at 5000
! @output do_aux 1 at 5000
! @output do_gun 1 at 5500
! @output do_aux 0 at 7000
! @output end 7000
  CONST robtarget p1 := [[300,-250,300],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p2 := [[300,250,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR clock clk;
  VAR intnum gun_changed;
  VAR intnum aux_changed;
  VAR triggdata gun_on;
  VAR triggdata gun_off;
  VAR triggdata far;
  VAR triggdata far_end;
  TRAP gun
    TPWrite "do_gun " + NumToStr(do_gun, 0) + " at " + NumToStr(1000 * ClkRead(clk), 0);
  ENDTRAP
  TRAP aux
    TPWrite "do_aux " + NumToStr(do_aux, 0) + " at " + NumToStr(1000 * ClkRead(clk), 0);
  ENDTRAP
  PROC main()
    MoveJ p1, v1000, fine, tool0;
    CONNECT gun_changed WITH gun;
    ISignalDO do_gun, 2, gun_changed;
    CONNECT aux_changed WITH aux;
    ISignalDO do_aux, 2, aux_changed;
    TriggIO gun_on, 50 \Start \DOp:=do_gun, 1;
    TriggIO gun_off, 0 \DOp:=do_gun, 0;
    TriggIO far, 600 \DOp:=do_aux, 1;
    TriggIO far_end, 600 \Start \DOp:=do_aux, 0;
    ClkStart clk;
    TriggL p2, v100, gun_on \T2:=gun_off, z10, tool0;
    TriggL Offs(p2, 0, 0, 200), v100, gun_on \T2:=far \T3:=far_end, fine, tool0;
    TPWrite "end " \Num:=Round(1000 * ClkRead(clk));
  ENDPROC
ENDMODULE

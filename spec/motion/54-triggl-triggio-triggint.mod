MODULE triggl_triggio_triggint
! @format 3
! @section 13
! @section 8
! @expect ok
! @statement-time 0
! @io io/trigg.io
! @description TriggL moves as MoveL (500 mm at v100 to a fine point: 5 s, the robot at p2 after it) and acts on its triggers as the TCP passes their positions (law T-distance, R-4.1-trigg1): TriggIO 100 mm from the start point (1 s), 0.5 s before the end point with \Time (4.5 s), 50 mm before the end point with \DODelay 0.2 s (4.5 s + 0.2 s), a group output 400 mm from the start (4 s); TriggInt 250 mm before the end point makes its interrupt occur at 2.5 s, and its trap finds the TCP there, at y = 0. The outputs are seen by interrupts on the signals, as the controller's signal changes at those times.
! @output do_gun 1 at 1000
! @output position at 2500 y 0
! @output go_code 5 at 4000
! @output do_gun 0 at 4500
! @output do_aux 1 at 4700
! @output end 5000 at p2 TRUE
  CONST robtarget p1 := [[300,-250,300],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p2 := [[300,250,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR clock clk;
  VAR intnum gun_changed;
  VAR intnum aux_changed;
  VAR intnum code_changed;
  VAR intnum halfway;
  VAR triggdata gun_on;
  VAR triggdata gun_off;
  VAR triggdata aux_on;
  VAR triggdata code;
  VAR triggdata middle;
  TRAP gun
    TPWrite "do_gun " + NumToStr(do_gun, 0) + " at " + NumToStr(1000 * ClkRead(clk), 0);
  ENDTRAP
  TRAP aux
    TPWrite "do_aux " + NumToStr(do_aux, 0) + " at " + NumToStr(1000 * ClkRead(clk), 0);
  ENDTRAP
  TRAP coded
    TPWrite "go_code " + NumToStr(go_code, 0) + " at " + NumToStr(1000 * ClkRead(clk), 0);
  ENDTRAP
  TRAP position
    VAR robtarget here;
    here := CRobT(\Tool:=tool0);
    TPWrite "position at " + NumToStr(1000 * ClkRead(clk), 0) + " y " + NumToStr(Abs(here.trans.y), 0);
  ENDTRAP
  PROC main()
    VAR robtarget there;
    MoveJ p1, v1000, fine, tool0;
    CONNECT gun_changed WITH gun;
    ISignalDO do_gun, 2, gun_changed;
    CONNECT aux_changed WITH aux;
    ISignalDO do_aux, 2, aux_changed;
    CONNECT code_changed WITH coded;
    ISignalGO go_code, code_changed;
    CONNECT halfway WITH position;
    TriggIO gun_on, 100 \Start \DOp:=do_gun, 1;
    TriggIO gun_off, 0.5 \Time \DOp:=do_gun, 0;
    TriggIO aux_on, 50 \DOp:=do_aux, 1 \DODelay:=0.2;
    TriggIO code, 400 \Start \GOp:=go_code, 5;
    TriggInt middle, 250, halfway;
    ClkStart clk;
    TriggL p2, v100, gun_on \T2:=gun_off \T3:=aux_on \T4:=code \T5:=middle, fine, tool0;
    there := CRobT(\Tool:=tool0);
    TPWrite "end " + NumToStr(1000 * ClkRead(clk), 0) + " at p2 " \Bool:=Distance(there.trans, p2.trans) < 0.01;
  ENDPROC
ENDMODULE

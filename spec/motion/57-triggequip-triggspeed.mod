MODULE triggequip_triggspeed
! @format 3
! @section 13
! @section 7
! @expect ok
! @statement-time 0
! @io io/trigg.io
! @description TriggEquip sets its output EquipLag s before the TCP reaches its position (100 mm from the start at v100, lag 0.2 s: 0.8 s), or after it with a negative lag (the end point at 5 s, lag -0.3 s: 5.3 s); with \Inhib TRUE then, it sets 0 instead of its value. TriggSpeed sets its analog output to ScaleValue times the TCP speed at its position, ScaleLag s earlier (R-4.1-trigg5): 0.05 x 100 mm/s = 5 from the start, 0 from 1.9 s (200 mm, lag 0.1 s). Before a TriggL is planned, a TriggSpeed whose ScaleValue with the programmed speed is beyond the analog output's range raises ERR_AO_LIM, one whose DipLag is beyond the Event Preset Time ERR_DIPLAG_LIM (ABB, TriggL); the robot has not moved.
! @output do_gun 1 at 800
! @output ao_flow 5 at 1000
! @output ao_flow 0 at 2000
! @output do_aux 0 at 2500
! @output end 5000
! @output do_gun 0 at 5300
! @output ERR_AO_LIM
! @output ERR_DIPLAG_LIM
! @output still at p2 TRUE
  CONST robtarget p1 := [[300,-250,300],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p2 := [[300,250,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PERS bool inhibit := TRUE;
  VAR clock clk;
  VAR intnum gun_changed;
  VAR intnum aux_changed;
  VAR intnum first_look;
  VAR intnum second_look;
  VAR triggdata early;
  VAR triggdata late;
  VAR triggdata inhibited;
  VAR triggdata flow_on;
  VAR triggdata flow_off;
  VAR triggdata too_much;
  VAR triggdata dip;
  TRAP gun
    TPWrite "do_gun " + NumToStr(do_gun, 0) + " at " + NumToStr(1000 * ClkRead(clk), 0);
  ENDTRAP
  TRAP aux
    TPWrite "do_aux " + NumToStr(do_aux, 0) + " at " + NumToStr(1000 * ClkRead(clk), 0);
  ENDTRAP
  TRAP look
    TPWrite "ao_flow " + NumToStr(ao_flow, 0) + " at " + NumToStr(1000 * ClkRead(clk), 0);
  ENDTRAP
  PROC try_move(VAR triggdata t)
    TriggL p1, v1000, t, fine, tool0;
  ERROR
    IF ERRNO = ERR_AO_LIM TPWrite "ERR_AO_LIM";
    IF ERRNO = ERR_DIPLAG_LIM TPWrite "ERR_DIPLAG_LIM";
    TRYNEXT;
  ENDPROC
  PROC main()
    VAR robtarget here;
    MoveJ p1, v1000, fine, tool0;
    Set do_aux;
    CONNECT gun_changed WITH gun;
    ISignalDO do_gun, 2, gun_changed;
    CONNECT aux_changed WITH aux;
    ISignalDO do_aux, 2, aux_changed;
    CONNECT first_look WITH look;
    CONNECT second_look WITH look;
    TriggEquip early, 100 \Start, 0.2 \DOp:=do_gun, 1;
    TriggEquip late, 0, -0.3 \DOp:=do_gun, 0;
    TriggEquip inhibited, 250 \Start, 0 \DOp:=do_aux, 1 \Inhib:=inhibit;
    TriggSpeed flow_on, 0 \Start, 0, ao_flow, 0.05;
    TriggSpeed flow_off, 200 \Start, 0.1, ao_flow, 0;
    ClkStart clk;
    ITimer \Single, 1, first_look;
    ITimer \Single, 2, second_look;
    TriggL p2, v100, early \T2:=late \T3:=inhibited \T4:=flow_on \T5:=flow_off, fine, tool0;
    TPWrite "end " \Num:=Round(1000 * ClkRead(clk));
    WaitTime 0.5;
    TriggSpeed too_much, 0 \Start, 0, ao_flow, 1E38;
    try_move too_much;
    TriggSpeed dip, 0 \Start, 0, ao_flow, 0.01 \DipLag:=0.2;
    try_move dip;
    here := CRobT(\Tool:=tool0);
    TPWrite "still at p2 " \Bool:=Distance(here.trans, p2.trans) < 0.01;
  ENDPROC
ENDMODULE

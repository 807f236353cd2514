MODULE moveabsj_time
! @format 3
! @section 13
! @expect ok
! @statement-time 0
! @description MoveAbsJ: all axes start and stop together, the slowest sets the time (T-joint): axis 6 turning 210 degrees at the IRB 120's 420 degrees/s takes 0.5 s, more than axis 5's 30 degrees at 320 degrees/s or the reorientation at v_ori; CJointT then reads the programmed axis angles.
! @output t 500
! @output axis 6 210
! @output axis 5 30
  VAR clock clk;
  CONST jointtarget j1 := [[0,0,0,0,30,210],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    VAR jointtarget now;
    ClkStart clk;
    MoveAbsJ j1, v1000, fine, tool0;
    TPWrite "t " \Num:=Round(1000 * ClkRead(clk));
    now := CJointT();
    TPWrite "axis 6 " \Num:=Round(now.robax.rax_6);
    TPWrite "axis 5 " \Num:=Round(now.robax.rax_5);
  ENDPROC
ENDMODULE

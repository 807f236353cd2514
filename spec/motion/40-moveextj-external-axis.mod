MODULE moveextj_axis
! @format 3
! @section 13
! @expect ok
! @statement-time 0
! @description MoveExtJ to a position of an external axis (eax_a 100) on the default robot, the IRB 120, which has no external axes: a component for an axis the robot does not have is ignored, as a deactivated mechanical unit's (doc/motion.md X-target, R-4.1-w), so the move moves no axis, takes no time, and CJointT still reads 9E9 for eax_a.
! @output before
! @output after 0.000 TRUE
  CONST jointtarget ext_a := [[0,0,0,0,0,0],[100,9E9,9E9,9E9,9E9,9E9]];
  VAR clock clk;
  PROC main()
    VAR jointtarget j;
    TPWrite "before";
    ClkStart clk;
    MoveExtJ ext_a, v1000, fine;
    j := CJointT();
    TPWrite "after " + NumToStr(ClkRead(clk), 3) + " " \Bool:=(j.extax.eax_a = 9E9);
  ENDPROC
ENDMODULE

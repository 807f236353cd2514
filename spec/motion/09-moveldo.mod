MODULE moveldo_case
! @format 3
! @section 13
! @expect ok
! @statement-time 0
! @io io/motion.io
! @description MoveLDO sets its output in the middle of the corner path: z10 on a 500 mm move at v100 and a 100 mm move after it, the corner runs from 4.9 s to 5.1 s (Z-clip) and do_glue changes at 5 s, seen by an interrupt on the signal.
! @output do_glue 1 at 5000
! @output end 6000
  CONST robtarget p1 := [[300,-250,300],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p2 := [[300,250,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR clock clk;
  VAR intnum glue;
  TRAP glued
    TPWrite "do_glue " + NumToStr(do_glue, 0) + " at " + NumToStr(1000 * ClkRead(clk), 0);
  ENDTRAP
  PROC main()
    MoveJ p1, v1000, fine, tool0;
    CONNECT glue WITH glued;
    ISignalDO do_glue, 1, glue;
    ClkStart clk;
    MoveLDO p2, v100, z10, tool0, do_glue, 1;
    MoveL Offs(p2, 0, 0, 100), v100, fine, tool0;
    TPWrite "end " \Num:=Round(1000 * ClkRead(clk));
    IDelete glue;
  ENDPROC
ENDMODULE

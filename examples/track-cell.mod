MODULE track_cell
  ! A long seam on a robot that stands on a track (examples/track-cell.robot: eax_a, along the
  ! world's x axis) beside a one-axis positioner (eax_b). Run it with
  !   rapid-sem run --robot examples/track-cell.robot examples/track-cell.mod
  ! Positions are in the world: the track is an integrated axis and the arm follows the seam
  ! while the track carries it (doc/motion.md, "External axes").
  CONST jointtarget home := [[0,0,0,0,90,0],[0,0,9E9,9E9,9E9,9E9]];
  CONST jointtarget turn := [[0,0,0,0,90,0],[9E9,90,9E9,9E9,9E9,9E9]];
  CONST robtarget seam_start := [[402,-100,300],[0,0,1,0],[-1,0,-1,0],[100,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget seam_end := [[1602,-100,300],[0,0,1,0],[-1,0,-1,0],[1300,9E9,9E9,9E9,9E9,9E9]];
  VAR clock clk;

  PROC main()
    VAR jointtarget j;
    VAR pos p;
    ConfL \Off;
    MoveAbsJ home, v1000, fine, tool0;
    ! The positioner turns the part while the robot waits.
    ClkStart clk;
    MoveExtJ turn, v1000, fine;
    TPWrite "part turned in " + NumToStr(ClkRead(clk), 2) + " s";
    MoveJ seam_start, v1000, fine, tool0;
    ClkReset clk;
    ClkStart clk;
    ! 1200 mm of seam at 100 mm/s: 12 s; the track follows at the same pace.
    MoveL seam_end, v100, fine, tool0;
    j := CJointT();
    p := CPos(\Tool:=tool0);
    TPWrite "seam done in " + NumToStr(ClkRead(clk), 2) + " s at x " + NumToStr(p.x, 1) + ", track at " + NumToStr(j.extax.eax_a, 1);
    MoveAbsJ home, v1000, fine, tool0;
  ENDPROC
ENDMODULE

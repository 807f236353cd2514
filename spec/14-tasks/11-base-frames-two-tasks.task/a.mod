MODULE base_frames_a
! @format 4
! @task T_ROB1
! @section 14
! @expect ok
! @base-frame T_ROB1=-200,0,800,1,0,0,0
! @base-frame T_ROB2=200,0,800,0,0,0,1
! @description Two motion tasks, each with its robot at its own base frame (MultiMove; MOC.cfg's ROBOT -base_frame_* per robot, --base-frame TASK=...; law F-base, R-bk-12): ROB_1 at [-200,0,800], ROB_2 at [200,0,800] turned 180 degrees about z, as a real cell mounts two IRB 120 facing each other. At the axes home each flange is [302,0,558] in its base frame: [102,0,1358] and [-102,0,1358] in the world. Each then moves to a world target that is [250,100,500] in its own base frame, [50,100,1300] and [-50,-100,1300]; CRobT reads each robot's TCP in the world, through its own base frame. B waits for A's line before it prints, so the order is fixed.
! @output A home 102 0 1358
! @output A at 50 100 1300
! @output B home -102 0 1358
! @output B at -50 -100 1300
  PERS bool a_done := FALSE;
  CONST jointtarget home := [[0,0,0,0,90,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget pa := [[50,100,1300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    VAR robtarget r;
    MoveAbsJ home, v1000, fine, tool0;
    r := CRobT(\Tool:=tool0);
    TPWrite "A home " + NumToStr(r.trans.x, 0) + " " + NumToStr(r.trans.y, 0) + " " + NumToStr(r.trans.z, 0);
    ConfL \Off;
    MoveL pa, v200, fine, tool0;
    r := CRobT(\Tool:=tool0);
    TPWrite "A at " + NumToStr(r.trans.x, 0) + " " + NumToStr(r.trans.y, 0) + " " + NumToStr(r.trans.z, 0);
    a_done := TRUE;
  ENDPROC
ENDMODULE

MODULE egm_pose_order
! @format 3
! @section 13
! @expect ok
! @egm-device EGMSensor=127.0.0.1:9
! @description The order of a pose-mode EGM process (ABB's EGMSetupUC \Pose, EGMActPose, EGMRunPose; doc/rulings.md R-13-egm2, R-13-egm6): EGMActPose before EGMSetupUC is ERR_ARGVALERR, and so are EGMActJoint of a process set up for pose mode, EGMRunPose before EGMActPose, a frame of type EGM_FRAME_JOINT, a convergence criterion with min above max, a stationary tool, and EGMRunJoint after EGMActPose; EGMActPose with every argument (frames of type BASE, TOOL, WOBJ and WORLD) activates the process, which stays connected.
! @output act before setup ERR_ARGVALERR
! @output connected 1
! @output act joint in pose mode ERR_ARGVALERR
! @output run before act ERR_ARGVALERR
! @output joint frame ERR_ARGVALERR
! @output min above max ERR_ARGVALERR
! @output stationary tool ERR_ARGVALERR
! @output activated 1
! @output run joint after act pose ERR_ARGVALERR
! @output done 1
  VAR egmident id;
  VAR num stage := 0;
  PERS tooldata fixed := [FALSE, [[0, 0, 100], [1, 0, 0, 0]], [1, [0, 0, 50], [1, 0, 0, 0], 0, 0, 0]];
  CONST pose frame := [[10, 0, 0], [1, 0, 0, 0]];
  PROC main()
    EGMGetId id;
    EGMActPose id, frame, EGM_FRAME_BASE, frame, EGM_FRAME_BASE;
    stage := 1;
    EGMSetupUC ROB_1, id, "default", "EGMSensor" \Pose;
    TPWrite "connected " \Num:=EGMGetState(id);
    EGMActJoint id;
    stage := 2;
    EGMRunPose id, EGM_STOP_HOLD \x;
    stage := 3;
    EGMActPose id, frame, EGM_FRAME_BASE, frame, EGM_FRAME_JOINT;
    stage := 4;
    EGMActPose id, frame, EGM_FRAME_BASE, frame, EGM_FRAME_BASE \rz:=[1, -1];
    stage := 5;
    EGMActPose id \Tool:=fixed, frame, EGM_FRAME_BASE, frame, EGM_FRAME_BASE;
    stage := 6;
    EGMActPose id, frame, EGM_FRAME_TOOL, frame, EGM_FRAME_WORLD;
    EGMActPose id \Tool:=tool0 \WObj:=wobj0, frame, EGM_FRAME_WOBJ, frame, EGM_FRAME_WOBJ \x:=[-1, 1] \y:=[-1, 1]
      \z:=[-1, 1] \rx:=[-1, 1] \ry:=[-1, 1] \rz:=[-1, 1] \LpFilter:=20 \SampleRate:=8 \MaxPosDeviation:=100
      \MaxSpeedDeviation:=50;
    TPWrite "activated " \Num:=EGMGetState(id);
    EGMRunJoint id, EGM_STOP_HOLD;
    stage := 7;
    TPWrite "done " \Num:=EGMGetState(id);
  ERROR
    IF ERRNO = ERR_ARGVALERR THEN
      TEST stage
      CASE 0: TPWrite "act before setup ERR_ARGVALERR";
      CASE 1: TPWrite "act joint in pose mode ERR_ARGVALERR";
      CASE 2: TPWrite "run before act ERR_ARGVALERR";
      CASE 3: TPWrite "joint frame ERR_ARGVALERR";
      CASE 4: TPWrite "min above max ERR_ARGVALERR";
      CASE 5: TPWrite "stationary tool ERR_ARGVALERR";
      CASE 6: TPWrite "run joint after act pose ERR_ARGVALERR";
      ENDTEST
      TRYNEXT;
    ENDIF
    RAISE;
  ENDPROC
ENDMODULE

MODULE sig_ui_egm
! @format 2
! @section 13
! @section 4.6
! @expect ok
! @description The FlexPendant dialogues (UIMsgBox, UIMessageBox, UINumEntry, UIListView with btnres, buttondata, icondata, listitem) and Externally Guided Motion (egmident, egm_minmax, EGMGetId, EGMSetupUC, EGMActPose, EGMRunPose, EGMStreamStart, EGMStop, EGMReset, EGMGetState, EGM_FRAME_ and EGM_STOP_ constants) as ABB documents them, and the path triggers TriggIO and TriggL.
  VAR btnres answer;
  VAR listitem items{2} := [["", "Run"], ["", "Stop"]];
  VAR string lines{2} := ["Line one", "Line two"];
  VAR num choice;
  VAR num force;
  VAR egmident egm;
  VAR triggdata gunOn;
  VAR signaldo doGun;
  CONST egm_minmax near := [-0.1, 0.1];
  CONST pose origin := [[0, 0, 0], [1, 0, 0, 0]];
  CONST robtarget p1 := [[500, 0, 400], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  PROC main()
    UIMsgBox "Ready?";
    UIMsgBox \Header:="Cell", "Part missing" \MsgLine2:="Load a part" \Buttons:=btnOKCancel
      \Icon:=iconWarning \Result:=answer \MaxTime:=30;
    answer := UIMessageBox(\Header:="Cell" \MsgArray:=lines \Wrap \Buttons:=btnYesNo
      \DefaultBtn:=resYes \Icon:=iconError);
    force := UINumEntry(\Header:="Force" \Message:="N" \Icon:=iconInfo \InitValue:=50
      \MinValue:=0 \MaxValue:=900 \AsInteger \MaxTime:=60);
    choice := UIListView(\Result:=answer \Header:="Menu", items \Buttons:=btnOK
      \Icon:=iconInfo \DefaultIndex:=1);
    IF answer = resOK OR answer = resNo TPWrite "chosen" \Num:=choice;
    EGMGetId egm;
    EGMSetupUC ROB_1, egm, "default", "EGMSensor:" \Pose;
    EGMActPose egm \Tool:=tool0 \WObj:=wobj0, origin, EGM_FRAME_BASE, origin,
      EGM_FRAME_BASE \x:=near \y:=near \z:=near \LpFilter:=20 \MaxSpeedDeviation:=100;
    EGMRunPose egm, EGM_STOP_HOLD \x \y \z \CondTime:=20 \RampInTime:=0.05;
    EGMStreamStart egm \SampleRate:=4;
    IF EGMGetState(egm) = EGM_STATE_RUNNING EGMStop egm, EGM_STOP_RAMP_DOWN;
    EGMReset egm;
    TriggIO gunOn, 0.1 \Time \DOp:=doGun, 1;
    TriggL p1, v100, gunOn, z10, tool0 \WObj:=wobj0;
  ENDPROC
ENDMODULE

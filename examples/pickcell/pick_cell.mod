MODULE PickCell
  ! A pick-and-place cell on an ABB IRB 120: parts arrive one at a time at a pick position, a
  ! vacuum gripper (doGripper) takes each, a sensor (diPartGripped) says it holds one, and the
  ! robot puts it into the next slot of a pallet of 2 rows of 3. A grip that fails is tried
  ! again twice; then the cell reports ERR_NOPART to its caller.
  ! Its tests: pick_cell_test.mod and nopart_test.mod (doc/testing.md).

  CONST robtarget pPick := [[300,-150,200],[0,0,1,0],[0,0,0,0],[9E+09,9E+09,9E+09,9E+09,9E+09,9E+09]];
  CONST robtarget pPallet := [[250,100,150],[0,0,1,0],[0,0,0,0],[9E+09,9E+09,9E+09,9E+09,9E+09,9E+09]];
  PERS tooldata tGripper := [TRUE,[[0,0,120],[1,0,0,0]],[0.8,[0,0,60],[1,0,0,0],0,0,0]];
  CONST num SAFE_Z := 80;
  CONST num SLOT_DX := 60;
  CONST num SLOT_DY := 80;
  CONST num MAX_GRIP_RETRIES := 2;
  CONST errnum ERR_NOPART := 50;
  CONST errnum ERR_SLOT := 51;
  VAR num nPicked := 0;
  VAR num nGripRetries := 0;

  ! The place of slot k (1..6) of the pallet: 3 slots per row along x, rows along y.
  FUNC robtarget SlotTarget(num k)
    VAR num row;
    VAR num col;
    IF k < 1 OR k > 6 THEN
      RAISE ERR_SLOT;
    ENDIF
    row := (k - 1) DIV 3;
    col := (k - 1) MOD 3;
    RETURN Offs(pPallet, col * SLOT_DX, row * SLOT_DY, 0);
  ENDFUNC

  ! The vacuum a part type needs, in kPa.
  FUNC num Vacuum(num partType)
    TEST partType
    CASE 1:
      RETURN 20;
    CASE 2, 3:
      RETURN 45;
    DEFAULT:
      RETURN 30;
    ENDTEST
  ENDFUNC

  PROC Grip()
    SetDO doGripper, 1;
    WaitDI diPartGripped, 1 \MaxTime:=1;
  ERROR
    IF ERRNO = ERR_WAIT_MAXTIME AND nGripRetries < MAX_GRIP_RETRIES THEN
      nGripRetries := nGripRetries + 1;
      SetDO doGripper, 0;
      WaitTime 0.2;
      SetDO doGripper, 1;
      RETRY;
    ENDIF
    SetDO doGripper, 0;
    RAISE ERR_NOPART;
  ENDPROC

  PROC Release()
    SetDO doGripper, 0;
    WaitTime 0.1;
  ENDPROC

  PROC PickAndPlace(num slot)
    VAR robtarget pSlot;
    pSlot := SlotTarget(slot);
    MoveJ Offs(pPick, 0, 0, SAFE_Z), v500, z20, tGripper;
    MoveL pPick, v100, fine, tGripper;
    Grip;
    MoveL Offs(pPick, 0, 0, SAFE_Z), v200, z10, tGripper;
    MoveJ Offs(pSlot, 0, 0, SAFE_Z), v500, z20, tGripper;
    MoveL pSlot, v100, fine, tGripper;
    Release;
    MoveL Offs(pSlot, 0, 0, SAFE_Z), v200, fine, tGripper;
    nPicked := nPicked + 1;
  ENDPROC

  PROC main()
    FOR k FROM 1 TO 6 DO
      PickAndPlace k;
    ENDFOR
  ENDPROC
ENDMODULE

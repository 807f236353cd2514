!rapid-sem: --io pick_cell.io
MODULE PickCellTest
  ! The tests of pick_cell.mod with a part at the pick position (pick_cell.io); run them with
  ! rapid-sem test examples/pickcell (doc/testing.md).

  PROC test_slot_offsets()
    VAR robtarget p;
    p := SlotTarget(5);
    AssertEqual 310, p.trans.x;
    AssertEqual 180, p.trans.y \Tol:=0.001;
    AssertEqualTarget Offs(pPallet, 60, 80, 0), p;
  ENDPROC

  PROC test_slot_out_of_range()
    VAR robtarget p;
    p := SlotTarget(7);
    AssertFail "SlotTarget(7) should raise ERR_SLOT";
  ERROR
    AssertErrno ERR_SLOT, ERRNO;
    RETURN;
  ENDPROC

  PROC test_vacuum_by_part_type()
    AssertEqual 20, Vacuum(1);
    AssertEqual 45, Vacuum(3);
    AssertEqual 30, Vacuum(9);
  ENDPROC

  PROC test_grip_holds_part()
    Grip;
    AssertSignal doGripper, 1;
    AssertSignal diPartGripped, 1;
    AssertEqual 0, nGripRetries;
  ENDPROC

  PROC test_pick_and_place_one_part()
    PickAndPlace 2;
    AssertAtTarget Offs(SlotTarget(2), 0, 0, SAFE_Z) \Tool:=tGripper;
    AssertSignal doGripper, 0;
    AssertEqual 1, nPicked;
  ENDPROC

  ! Deliberately wrong (doc/testing.md shows how a failure reads): two cycles place two parts.
  PROC test_two_cycles_count()
    PickAndPlace 1;
    PickAndPlace 2;
    AssertEqual 3, nPicked \Msg:="parts on the pallet";
  ENDPROC
ENDMODULE

!rapid-sem: --io nopart.io
MODULE NoPartTest
  ! The error recovery of pick_cell.mod when no part arrives (nopart.io): Grip tries twice more,
  ! then raises ERR_NOPART with the gripper off.

  PROC test_grip_gives_up()
    Grip;
    AssertFail "Grip should raise ERR_NOPART";
  ERROR
    AssertErrno ERR_NOPART, ERRNO;
    AssertEqual MAX_GRIP_RETRIES, nGripRetries;
    AssertSignal doGripper, 0;
    RETURN;
  ENDPROC
ENDMODULE

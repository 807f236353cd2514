MODULE Reach
  ! MOC.cfg's type is the library's IRB 120; its arm's bounds narrow axis 1 to +-0.5 rad
  ! (+-28.6 degrees), and leave axis 2's range as it is (R-bk-5).
  PROC main()
    MoveAbsJ [[25, 0, 0, 0, 30, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]], v1000, fine, tool0;
    TPWrite "25 degrees: within the bounds";
    MoveAbsJ [[35, 0, 0, 0, 30, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]], v1000, fine, tool0;
    TPWrite "35 degrees";
  ENDPROC
ENDMODULE

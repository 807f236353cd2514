MODULE undo_long_jump
! @format 3
! @section 7.2
! @section 1.2
! @expect ok
! @description A long jump abandons every routine between the error and the recovery point; their UNDO handlers run, innermost first, before the recovery point's handler (section 7.2: UNDO for routines that cannot complete because of a long jump).
! @output r3 undo
! @output r2 undo
! @output r1 undo
! @output main recovery point
! @exit 0
  PROC main()
    r1;
  ERROR (56)
    TPWrite "main recovery point";
    RETURN;
  ENDPROC
  PROC r1()
    r2;
  UNDO
    TPWrite "r1 undo";
  ENDPROC
  PROC r2()
    r3;
  UNDO
    TPWrite "r2 undo";
  ENDPROC
  PROC r3()
    RAISE 56;
  UNDO
    TPWrite "r3 undo";
  ENDPROC
ENDMODULE

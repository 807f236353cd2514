MODULE and_guards_index
! @format 3
! @section 3.1
! @section 3.6
! @expect ok
! @description Because AND skips its right operand when the left one is FALSE (section 3.1), i <= 3 AND a{i} = 0 does not index a{4}: no ERR_OUTOFBND is raised.
! @output guarded
! @exit 0
  VAR num a{3} := [0, 0, 0];
  PROC main()
    VAR num i := 4;
    IF i <= 3 AND a{i} = 0 THEN
      TPWrite "wrong";
    ELSE
      TPWrite "guarded";
    ENDIF
  ENDPROC
ENDMODULE

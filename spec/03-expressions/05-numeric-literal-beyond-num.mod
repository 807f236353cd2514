MODULE numeric_literal_beyond_num
! @format 2
! @section 2.5
! @section 2.13
! @expect semantic-error 10:10
! @description A numeric literal must lie within the value range of IEEE 754 (§2.5); a literal whose context makes it a num is a single precision number (§2.13), so 1E39 is out of range there. In a dnum context it is within range.
  PROC main()
    VAR num x;
    VAR dnum d := 1E39;
    x := 1E39;
    d := -1E300;
  ENDPROC
ENDMODULE

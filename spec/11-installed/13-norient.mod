MODULE norient_use
! @format 3
! @section 13
! @expect ok
! @description NOrient normalises a slightly un-normalised quaternion (error between 0.00001 and 0.1, installed-facts.md section 3) and leaves a normalised one as it is.
! @output fixed=TRUE
! @output unchanged=TRUE
! @exit 0
  PROC main()
    VAR orient slightly := [0.99, 0, 0, 0];
    VAR orient unit := [0.5, 0.5, 0.5, 0.5];
    VAR orient r;
    r := NOrient(slightly);
    TPWrite "fixed=" \Bool:=Abs(r.q1 - 1) < 0.00001 AND r.q2 = 0 AND r.q3 = 0 AND r.q4 = 0;
    r := NOrient(unit);
    TPWrite "unchanged=" \Bool:=r = unit;
  ENDPROC
ENDMODULE

MODULE index_huge_integer
! @format 3
! @section 3.6
! @section 12
! @expect ok
! @description An index that is a whole number far beyond the dimension (1E20, which a num holds exactly) is an integer outside 1..dimension: ERR_OUTOFBND, not ERR_NOTINTVAL (doc/rulings.md R-3.6); a handler sees the number.
! @output before
! @output handled 1020
! @output after
! @exit 0
  VAR num a{3} := [1, 2, 3];
  PROC main()
    VAR num i := 1E20;
    VAR num x;
    TPWrite "before";
    x := a{i};
    TPWrite "after";
  ERROR
    TPWrite "handled " \Num:=ERRNO;
    TRYNEXT;
  ENDPROC
ENDMODULE

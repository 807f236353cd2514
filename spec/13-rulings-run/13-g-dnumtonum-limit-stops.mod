MODULE rulings_dnumtonum_limit
! @format 3
! @section 13
! @section 7.1
! @expect ok
! @description R-13-g: DnumToNum of a dnum beyond the range of num (1E39) is ERR_NUM_LIMIT; with no handler the task stops at the statement that calls it.
! @output 1E38 fits
! @exit 1
! @error ERR_NUM_LIMIT 16:5
  PROC main()
    VAR dnum d := 1E38;
    VAR num x;
    x := DnumToNum(d);
    TPWrite "1E38 fits";
    d := d * 10;
    x := DnumToNum(d);
    TPWrite "not reached";
  ENDPROC
ENDMODULE

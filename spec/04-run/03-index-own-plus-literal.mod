MODULE index_own_plus_literal
! @format 3
! @section 3.6
! @section 3.12
! @section 12
! @expect ok
! @description An index written as an own slot plus or minus a literal (a{j + 1}, a{j - 1}), read and assigned: within the bounds it is the element; the sum is a num rounded to single first (16777216 + 1 is 16777216, outside 1..3: ERR_OUTOFBND); a non-integer sum is ERR_NOTINTVAL; 0 and 4 are ERR_OUTOFBND.
! @output 2 9 9
! @output handled 1020
! @output handled 1020
! @output handled 1018
! @output handled 1020
! @output done 9
! @exit 0
  VAR num a{3} := [1, 2, 3];
  PROC main()
    VAR num j := 1;
    VAR num x;
    a{j + 2} := 9;
    TPWrite NumToStr(a{j + 1}, 0) + " " + NumToStr(a{j - (-2)}, 0) + " " + NumToStr(a{3 - 0}, 0);
    j := 3;
    x := a{j + 1};
    j := 1;
    a{j - 1} := 5;
    j := 1.5;
    x := a{j + 1};
    j := 16777216;
    x := a{j + 1};
    TPWrite "done " \Num:=a{3};
  ERROR
    TPWrite "handled " \Num:=ERRNO;
    TRYNEXT;
  ENDPROC
ENDMODULE

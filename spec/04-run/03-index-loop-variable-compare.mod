MODULE index_loop_variable_compare
! @format 3
! @section 3.6
! @section 3.12
! @section 4.18
! @section 4.17
! @expect ok
! @description Two elements compared, each indexed by a FOR variable or a FOR variable plus a literal (a{j} > a{j + 1}): the left element is read first, then the right one; an index beyond the dimension is ERR_OUTOFBND and a non-integer one ERR_NOTINTVAL, raised by the comparison's statement (the left one's when both are wrong).
! @output swaps 1
! @output handled 1018 swaps 1
! @output handled 1018 swaps 1
! @output handled 1020 swaps 1
! @output handled 1018 swaps 1
! @exit 0
  VAR num a{3} := [3, 1, 2];
  PROC main()
    VAR num swaps := 0;
    FOR j FROM 1 TO 3 DO
      IF a{j} > a{j + 1} swaps := swaps + 1;
      IF j = 1 TPWrite "swaps " \Num:=swaps;
      IF a{j + 0.5} >= a{j + 5} swaps := swaps + 10;
    ENDFOR
  ERROR
    TPWrite "handled " + NumToStr(ERRNO, 0) + " swaps " + NumToStr(swaps, 0);
    TRYNEXT;
  ENDPROC
ENDMODULE

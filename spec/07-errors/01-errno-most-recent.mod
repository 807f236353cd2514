MODULE errno_most_recent
! @format 3
! @section 7.1
! @expect ok
! @description Each error sets ERRNO anew: a later error in the same routine is seen with its own number.
! @output 11
! @output 12
! @exit 0
  PROC main()
    RAISE 11;
    RAISE 12;
  ERROR
    TPWrite "" \Num:=ERRNO;
    TRYNEXT;
  ENDPROC
ENDMODULE

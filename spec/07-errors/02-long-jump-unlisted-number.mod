MODULE long_jump_unlisted_number
! @format 3
! @section 7.2
! @expect ok
! @description A recovery point catches only the numbers of its list: 57 is not in main's ERROR (56), no recovery point is found, and the error is handled in the calling routine's handler as usual (section 7.2, last step of the search).
! @output middle handler 57
! @output after deep
! @exit 0
  PROC main()
    middle;
  ERROR (56)
    TPWrite "wrong: main recovery point";
    RETURN;
  ENDPROC
  PROC middle()
    deep;
    TPWrite "after deep";
  ERROR
    TPWrite "middle handler " \Num:=ERRNO;
    TRYNEXT;
  ENDPROC
  PROC deep()
    RAISE 57;
  ENDPROC
ENDMODULE

MODULE long_jump_no_reraise
! @format 3
! @section 7.2
! @expect ok
! @description An error raised in a routine without error handler leaves it at once; the recovery point of main that names the error takes it, and the ordinary handler of the routine in between is skipped.
! @output main recovery point 56
! @exit 0
  PROC main()
    middle;
  ERROR (56)
    TPWrite "main recovery point " \Num:=ERRNO;
    RETURN;
  ENDPROC
  PROC middle()
    deep;
  ERROR
    TPWrite "wrong: middle handler";
    TRYNEXT;
  ENDPROC
  PROC deep()
    RAISE 56;
  ENDPROC
ENDMODULE

MODULE raise_number_limits
! @format 3
! @section 4.11
! @section 7.1
! @expect ok
! @description The user error numbers are 1 to 90 (sections 4.11, 7.1): RAISE 1 and RAISE 90 raise those errors.
! @output errno=1
! @output errno=90
! @exit 0
  VAR num n := 1;
  PROC main()
    RAISE n;
    n := 90;
    RAISE n;
  ERROR
    TPWrite "errno=" \Num:=ERRNO;
    TRYNEXT;
  ENDPROC
ENDMODULE

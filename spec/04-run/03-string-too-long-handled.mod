MODULE string_too_long_handled
! @format 3
! @section 2.13
! @section 7.1
! @expect ok
! @description ERR_STRTOOLNG can be handled; the target keeps its old value because the assignment did not take place.
! @output strtoolng=TRUE
! @output len=70
! @exit 0
  PROC main()
    VAR string s := "0123456789012345678901234567890123456789012345678901234567890123456789";
    s := s + "0123456789a";
    TPWrite "len=" \Num:=StrLen(s);
  ERROR
    TPWrite "strtoolng=" \Bool:=ERRNO = ERR_STRTOOLNG;
    TRYNEXT;
  ENDPROC
ENDMODULE

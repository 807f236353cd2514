MODULE record_two_trailing_comment_line
! @section 2.10
! @expect ok
! @description Without --strict, comment lines of their own inside RECORD are accepted (dialect extension, doc/dialect.md); with it this is refused (the -strict twin).
  RECORD r
    num a;
    ! alone, followed by another comment line
    ! alone on the last line
  ENDRECORD
ENDMODULE

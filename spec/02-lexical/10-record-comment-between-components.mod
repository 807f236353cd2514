MODULE record_comment_between_component
! @section 2.10
! @expect ok
! @description Without --strict, comment lines of their own inside RECORD are accepted (dialect extension, doc/dialect.md); with it this is refused (the -strict twin).
  RECORD r
    num a;
    ! alone on its line, not the last line
    num b;
  ENDRECORD
ENDMODULE

MODULE record_comment_last_line
! @section 2.10
! @expect ok
! @description Inside RECORD a comment may stand on a line of its own on the last line.
  RECORD r
    num a;
    num b;
    ! alone on the last line
  ENDRECORD
ENDMODULE

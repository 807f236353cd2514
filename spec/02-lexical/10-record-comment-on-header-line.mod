MODULE record_comment_on_header_line
! @section 2.10
! @expect ok
! @description A comment on the line of RECORD <identifier> does not stand alone on its line.
  RECORD r ! on the line of RECORD, not alone
    num a;
  ENDRECORD
ENDMODULE

MODULE record_comment_between_strict
! @section 2.10
! @expect syntax-error 8:5
! @options strict
! @description In strict mode, inside RECORD a comment may not stand on a line of its own between components.
  RECORD r
    num a;
    ! alone on its line, not the last line
    num b;
  ENDRECORD
ENDMODULE

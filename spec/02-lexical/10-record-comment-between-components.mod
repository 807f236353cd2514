MODULE record_comment_between_component
! @section 2.10
! @expect syntax-error 7:5
! @description Inside RECORD a comment may not stand on a line of its own between components.
  RECORD r
    num a;
    ! alone on its line, not the last line
    num b;
  ENDRECORD
ENDMODULE

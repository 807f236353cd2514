MODULE record_comment_after_component
! @section 2.10
! @expect ok
! @description Inside RECORD a comment may follow a component on the same line.
  RECORD r
    num a; ! after a component
    num b; ! after another one
  ENDRECORD
ENDMODULE

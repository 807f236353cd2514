MODULE record_only_a_comment
! @section 2.10
! @section 2.14
! @expect syntax-error 7:3
! @description A record component list holds at least one component: a comment (allowed on the RECORD line) is not one.
  RECORD r ! a comment on the line of RECORD, and no component
  ENDRECORD
ENDMODULE

MODULE record_manual_example
! @section 2.10
! @section 2.14
! @expect ok
! @description Without --strict, comment lines of their own inside RECORD are accepted (dialect extension, doc/dialect.md); with it this is refused (the -strict twin).
  RECORD my_rec
    ! DISALLOWED COMMENT
    num mynum; ! allowed comment (not separate line)
    string mystring;
    ! allowed comment on last line
  ENDRECORD
ENDMODULE

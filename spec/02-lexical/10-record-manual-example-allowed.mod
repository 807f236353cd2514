MODULE record_manual_example_allowed
! @section 2.10
! @section 2.14
! @expect ok
! @description The example of sections 2.10 and 2.14 without its DISALLOWED line.
  RECORD my_rec
    num mynum; ! allowed comment (not separate line)
    string mystring;
    ! allowed comment on last line
  ENDRECORD
ENDMODULE

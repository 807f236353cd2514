MODULE record_manual_example_strict
! @section 2.10
! @section 2.14
! @expect syntax-error 8:5
! @options strict
! @description In strict mode, the example of sections 2.10 and 2.14 as printed: the comment alone on a line before a component is refused.
  RECORD my_rec
    ! DISALLOWED COMMENT
    num mynum; ! allowed comment (not separate line)
    string mystring;
    ! allowed comment on last line
  ENDRECORD
ENDMODULE

MODULE reference_expression_non_value
! @format 2
! @section 2.16
! @section 3.12
! @expect semantic-error 10:13
! @description Table of section 2.16, row object used in an expression, column non-value: illegal (and = takes value types only); refused at the object.
  VAR iodev logfile;
  VAR bool same;
  PROC main()
    same := logfile = 0;
  ENDPROC
ENDMODULE

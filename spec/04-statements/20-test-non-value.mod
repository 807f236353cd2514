MODULE test_non_value
! @format 2
! @section 4.20
! @section 2.16
! @expect semantic-error 9:10
! @description The test expression must be of a value or semi-value type; a non-value object is refused at the expression.
  VAR iodev logfile;
  PROC main()
    TEST logfile
    DEFAULT:
      DebugBreak;
    ENDTEST
  ENDPROC
ENDMODULE

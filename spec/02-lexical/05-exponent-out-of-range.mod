MODULE exponent_out_of_range
! @section 2.5
! @section 1.4
! @expect lexical-error 8:10
! @description The example of a lexical error in section 1.4: the exponent is out of range.
  VAR num b;
  PROC main()
    b := 2E52786;
  ENDPROC
ENDMODULE

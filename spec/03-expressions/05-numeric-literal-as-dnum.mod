MODULE numeric_literal_as_dnum
! @format 2
! @section 3.5
! @section 2.13
! @expect ok
! @description A numeric literal takes the numeric type its context asks for: section 2.13's value := 2E+43 on a dnum, and literal operands of dnum operations.
  VAR dnum value;
  VAR dnum big := 4503599627370496;
  PROC main()
    value := 2E+43;
    big := big + 1;
    value := value * 2 - big;
  ENDPROC
ENDMODULE

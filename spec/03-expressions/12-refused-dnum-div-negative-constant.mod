MODULE refused_dnum_div_negative
! @format 2
! @section 3.12
! @expect semantic-error 10:10
! @description Note (c) of section 3.12: dnum DIV operands must represent integers >= 0; a constant -4 is refused at the start of the operation.
  CONST dnum minus_four := -4;
  CONST dnum two := 2;
  VAR dnum r;
  PROC main()
    r := minus_four DIV two;
  ENDPROC
ENDMODULE

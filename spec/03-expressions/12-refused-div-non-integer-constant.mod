MODULE refused_div_non_integer_constant
! @format 2
! @section 3.12
! @expect semantic-error 8:10
! @description Note (b) of section 3.12: DIV operands must represent integer values; a constant operand 2.5 is refused at the start of the operation.
  VAR num r;
  PROC main()
    r := 7 DIV 2.5;
  ENDPROC
ENDMODULE

MODULE refused_xor_num
! @format 2
! @section 3.12
! @expect semantic-error 10:10
! @description XOR takes bool operands; bool XOR num is refused at the left operand.
  VAR num n;
  VAR bool b;
  VAR bool r;
  PROC main()
    r := b XOR n;
  ENDPROC
ENDMODULE

MODULE refused_and_num
! @format 2
! @section 3.12
! @expect semantic-error 10:10
! @description AND takes bool operands; refused at the left operand.
  VAR num n;
  VAR bool b;
  VAR bool r;
  PROC main()
    r := n AND b;
  ENDPROC
ENDMODULE

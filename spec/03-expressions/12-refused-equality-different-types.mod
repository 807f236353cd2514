MODULE refused_equality_different_types
! @format 2
! @section 3.12
! @expect semantic-error 10:10
! @description = requires both operands of equal type; num = string is refused at the left operand.
  VAR num n;
  VAR string s;
  VAR bool r;
  PROC main()
    r := n = s;
  ENDPROC
ENDMODULE

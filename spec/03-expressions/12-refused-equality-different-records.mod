MODULE refused_equality_different
! @format 2
! @section 3.12
! @expect semantic-error 15:10
! @description = requires both operands of equal type; pos and a user record are refused at the left operand.
  RECORD vector
    num x;
    num y;
    num z;
  ENDRECORD
  VAR pos p;
  VAR vector v;
  VAR bool r;
  PROC main()
    r := p = v;
  ENDPROC
ENDMODULE

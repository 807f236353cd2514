MODULE refused_pos_comparison
! @format 2
! @section 3.12
! @expect semantic-error 10:10
! @description > takes num or dnum operands; pos is refused at the left operand.
  VAR pos p1;
  VAR pos p2;
  VAR bool r;
  PROC main()
    r := p1 > p2;
  ENDPROC
ENDMODULE

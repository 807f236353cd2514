MODULE refused_pos_div_num
! @format 2
! @section 3.12
! @expect semantic-error 10:10
! @description DIV takes num or dnum operands only; refused at the left operand.
  VAR pos p;
  VAR num k;
  VAR pos r;
  PROC main()
    r := p DIV k;
  ENDPROC
ENDMODULE

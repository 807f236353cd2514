MODULE vector_addition_and_subtraction
! @format 2
! @section 3.12
! @expect ok
! @description Rows + and - pos, pos -> pos.
  VAR pos p1;
  VAR pos p2;
  VAR pos r;
  PROC main()
    r := p1 + p2;
    r := p1 - p2;
  ENDPROC
ENDMODULE

MODULE persistent_declaration
! @section 2.23
! @expect ok
! @description The persistent declarations of sections 2.23 and 14, with and without a literal expression.
  PERS num pcounter := 0;
  ! 2 x 2 matrix
  PERS num grid{2, 2} := [[0, 0], [0, 0]];
  PERS num state;
  PERS num neg := -1;
ENDMODULE

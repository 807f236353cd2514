MODULE dim
! @section 2.22
! @expect ok
! @description <dim> ::= <constant expression>.
  CONST num n := 3;
  VAR num a{n};
  VAR num b{2 * n, n + 1};
  VAR num c{(n)};
ENDMODULE

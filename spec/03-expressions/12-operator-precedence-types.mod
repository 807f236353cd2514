MODULE operator_precedence_types
! @format 2
! @section 3.12
! @section 3.1
! @expect ok
! @description The types follow the evaluation order of section 3.1: a + b * c, a < b AND c < d, NOT a OR b.
  VAR num a;
  VAR num b;
  VAR num c;
  VAR num d;
  VAR bool x;
  VAR bool y;
  VAR bool r;
  PROC main()
    a := a + b * c;
    r := a < b AND c < d;
    r := NOT x OR y;
    r := x AND y OR a > b;
  ENDPROC
ENDMODULE

MODULE literal_initialisers
! @format 2
! @section 2.23
! @section 3.3
! @expect ok
! @description Literal expressions: literals, numeric literals with a sign, aggregates of literal expressions (the examples of sections 2.23 and 3.3).
  PERS num pcounter := 0;
  PERS num grid{2, 2} := [[0, 0], [0, 0]];
  PERS pos refpnt := [100, 778, 1183];
  PERS num diameter := 24.43;
  PERS num below := -5;
  PERS num above := +2;
  PERS pos offset := [-1.5, +2, -0.5E2];
  PERS string name := "cell 1";
  PERS bool active := TRUE;
  PERS pose frame := [[0, 0, 0], [1, 0, 0, 0]];
ENDMODULE

MODULE weldpath
  ! (CAD) generated module
  CONST pose posearr{2} := [[[234.7, 1136.7, 10.2], [1, 0, 0, 0]], [[77.2, 68.1, 554.7], [1, 0, 0, 0]]];
ENDMODULE

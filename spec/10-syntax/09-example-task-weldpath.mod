MODULE weldpath ! (CAD) generated module
! @section 9.2
! @expect ok
! @description The third module of the task of section 9.2: of its 768 poses only the first and the last are kept.
  CONST pose posearr{2} := [ [[234.7, 1136.7, 10.2], [1, 0, 0,
        0]], [[77.2, 68.1, 554.7], [1, 0, 0, 0]] ];
ENDMODULE

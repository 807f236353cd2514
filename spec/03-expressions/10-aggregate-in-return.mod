MODULE aggregate_in_return
! @format 2
! @section 3.10
! @section 4.10
! @expect ok
! @description The function's type determines a returned aggregate's type.
  FUNC pos origin()
    RETURN [0, 0, 0];
  ENDFUNC
  FUNC pose identity()
    RETURN [[0, 0, 0], [1, 0, 0, 0]];
  ENDFUNC
ENDMODULE

MODULE parameter
! @section 3.9
! @expect ok
! @description Entire parameters, parameter elements and components.
  PROC p(VAR num arr{*}, INOUT pos q, num n)
    arr{1} := q.x + n;
    q.y := arr{2};
    n := n + 1;
  ENDPROC
ENDMODULE

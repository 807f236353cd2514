MODULE constant_and_short_circuit
! @format 2
! @section 3.2
! @section 3.1
! @expect ok
! @description A constant expression is evaluated as any expression (§3.1): the right operand of AND is not evaluated when the left one is FALSE, so the division by zero there never happens.
  CONST num zero := 0;
  CONST bool never := FALSE AND 1 / zero > 0;
  PROC main()
  ENDPROC
ENDMODULE

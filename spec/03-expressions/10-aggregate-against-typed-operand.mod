MODULE aggregate_against_typed_operand
! @format 2
! @section 3.10
! @expect ok
! @description Ruling: the other operand of = or <> is a context that determines an aggregate's type.
  VAR pos p1;
  VAR num a;
  PROC main()
    IF p1 = [1, -100, 12] THEN
      a := 0;
    ENDIF
    IF [0, 0, 0] <> p1 a := 1;
  ENDPROC
ENDMODULE

MODULE aggregates_both_operands
! @format 2
! @section 3.10
! @expect semantic-error 9:8
! @description Section 3.10: IF [1,-100,12] = [a,b,b] is illegal, since the type of neither aggregate can be determined by the context; refused at the first aggregate.
  VAR num a;
  VAR num b;
  PROC main()
    IF [1, -100, 12] = [a, b, b] THEN
      a := 0;
    ENDIF
  ENDPROC
ENDMODULE

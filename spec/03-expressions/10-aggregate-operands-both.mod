MODULE aggregate_operands_both
! @format 2
! @section 3.10
! @section 3.12
! @expect semantic-error 9:10
! @description Ruling R-3.10-operand1: when both operands of + are aggregates, neither gives the other a type; refused at the first aggregate.
  VAR pos q;
  PROC main()
    q := [1, 2, 3] + [4, 5, 6];
  ENDPROC
ENDMODULE

MODULE aggregate_operand_no_row
! @format 2
! @section 3.10
! @section 3.12
! @expect semantic-error 9:10
! @description Ruling R-3.10-operand1: no row of the operator table adds an aggregate (a pos or orient) to a num, so the context does not determine the aggregate's type; refused at the aggregate.
  VAR pos q;
  PROC main()
    q := [1, 2, 3] + 1;
  ENDPROC
ENDMODULE

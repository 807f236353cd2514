MODULE conformant_array_rank_mismatch
! @format 2
! @section 5.2
! @expect semantic-error 10:12
! @description The number of dimensions of an array argument must match the parameter's; a {2,3} array for {*} is refused at the argument.
  VAR num plane{2, 3};
  PROC arrmul(VAR num array{*}, num factor)
  ENDPROC
  PROC main()
    arrmul plane, 2;
  ENDPROC
ENDMODULE

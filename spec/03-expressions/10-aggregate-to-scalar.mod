MODULE aggregate_to_scalar
! @format 2
! @section 3.10
! @expect semantic-error 8:10
! @description An aggregate denotes an array or record value: a num context cannot type it; refused at the aggregate.
  VAR num n;
  PROC main()
    n := [1, 2];
  ENDPROC
ENDMODULE

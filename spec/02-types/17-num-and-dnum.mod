MODULE num_and_dnum
! @format 2
! @section 2.17
! @expect semantic-error 9:10
! @description num and dnum are different types: a dnum variable is not assigned to a num; refused at the right-hand side.
  VAR num n;
  VAR dnum d;
  PROC main()
    n := d;
  ENDPROC
ENDMODULE

MODULE refused_num_times_dnum
! @format 2
! @section 3.12
! @expect semantic-error 10:10
! @description num * dnum is no row of the table; refused at the left operand.
  VAR num n;
  VAR dnum d;
  VAR dnum r;
  PROC main()
    r := n * d;
  ENDPROC
ENDMODULE

MODULE refused_num_divided_by_pos
! @format 2
! @section 3.12
! @expect semantic-error 10:10
! @description num / pos is no row of the table (only pos / num); refused at the left operand.
  VAR num k;
  VAR pos p;
  VAR pos r;
  PROC main()
    r := k / p;
  ENDPROC
ENDMODULE

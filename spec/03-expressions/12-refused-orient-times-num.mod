MODULE refused_orient_times_num
! @format 2
! @section 3.12
! @expect semantic-error 10:10
! @description orient * num is no row of the table; refused at the left operand.
  VAR orient o;
  VAR num k;
  VAR orient r;
  PROC main()
    r := o * k;
  ENDPROC
ENDMODULE

MODULE index_dnum
! @format 2
! @section 3.6
! @expect semantic-error 9:7
! @description An index must represent an integer value of type num (section 2.13's num); a dnum variable is refused at the index.
  VAR num a{3};
  VAR dnum k := 1;
  PROC main()
    a{k} := 2;
  ENDPROC
ENDMODULE

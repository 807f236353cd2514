MODULE index_not_num
! @format 2
! @section 3.6
! @expect semantic-error 8:7
! @description An index expression must be a num; refused at the string index.
  VAR num a{3};
  PROC main()
    a{"1"} := 2;
  ENDPROC
ENDMODULE

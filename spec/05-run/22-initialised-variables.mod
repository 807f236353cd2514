MODULE initialised_variables
! @format 3
! @section 2.22
! @section 2.24
! @expect ok
! @description Section 2.22's initialised variables and section 2.24's constant array hold their initial values when the program starts.
! @output John Smith
! @output 50
! @output 9
! @output 1021
! @exit 0
  VAR string author_name := "John Smith";
  VAR pos start := [100, 100, 50];
  VAR num maxno{10} := [1, 2, 3, 9, 8, 7, 6, 5, 4, 3];
  CONST pos seq{3} := [[614, 778, 1020], [914, 998, 1021], [814, 998, 1022]];
  PROC main()
    TPWrite author_name;
    TPWrite "" \Num:=start.z;
    TPWrite "" \Num:=maxno{4};
    TPWrite "" \Num:=seq{2}.z;
  ENDPROC
ENDMODULE

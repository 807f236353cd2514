MODULE index_of_parameter_and_constant
! @format 2
! @section 3.6
! @section 3.8
! @section 3.9
! @expect ok
! @description Constants and parameters are indexed and their components selected as variables are (sections 3.8, 3.9).
  CONST pos corners{2} := [[0, 0, 0], [1, 1, 1]];
  VAR num x;
  PROC main()
    x := corners{2}.z;
  ENDPROC
  PROC scan(pos points{*}, num k)
    x := points{k}.y + corners{k}.x;
  ENDPROC
ENDMODULE

MODULE constant
! @section 3.8
! @expect ok
! @description Entire constants, constant elements and components.
  CONST pos seq{2} := [[1, 2, 3], [4, 5, 6]];
  CONST pos origin := [0, 0, 0];
  VAR num x;
  PROC main()
    x := seq{2}.y;
    x := origin.z + seq{1}.x;
  ENDPROC
ENDMODULE

MODULE white_space_kinds
! @section 2.2
! @section 2.10
! @expect ok
! @description Spaces, tabs, form feeds and newlines all separate tokens.
  VAR	num	x;
  VARnumy;
  PROC main()
    x	:=1;
    y :=
      2;
  ENDPROC
ENDMODULE

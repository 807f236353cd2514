MODULE alias_of_record_equal
! @format 2
! @section 2.17
! @expect ok
! @description An alias of pos is equal to pos, also inside aggregates and arrays.
  ALIAS pos point;
  VAR point pt;
  VAR pos p;
  VAR point path{2};
  VAR pos track{2};
  PROC main()
    pt := p;
    p := pt;
    path := track;
    path := [p, pt];
  ENDPROC
ENDMODULE

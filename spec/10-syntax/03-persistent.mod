MODULE persistent
! @section 3.7
! @expect ok
! @description Entire persistents, persistent elements and components.
  PERS num pa{3} := [1, 2, 3];
  PERS pos pp := [0, 0, 0];
  PERS pos refpnt := [0, 0, 0];
  PROC main()
    pa{2} := pa{1};
    pp.x := pa{3};
    pp := refpnt;
  ENDPROC
ENDMODULE

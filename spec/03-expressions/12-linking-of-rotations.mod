MODULE linking_of_rotations
! @format 2
! @section 3.12
! @expect ok
! @description Row * orient * orient -> orient.
  VAR orient o1;
  VAR orient o2;
  VAR orient r;
  PROC main()
    r := o1 * o2;
  ENDPROC
ENDMODULE

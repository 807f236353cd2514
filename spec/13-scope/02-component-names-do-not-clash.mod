MODULE component_names_do_not_clash
! @format 2
! @section 2.14
! @section 2.20
! @expect ok
! @description Record component names are not module objects: a component and a data object may share a name.
  RECORD point_rec
    num x;
    num y;
  ENDRECORD
  VAR num x;
  VAR point_rec pr;
  PROC main()
    pr.x := x;
  ENDPROC
ENDMODULE

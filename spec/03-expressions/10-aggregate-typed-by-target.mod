MODULE aggregate_typed_by_target
! @format 2
! @section 3.10
! @expect ok
! @description Section 3.10: the aggregate's type pos is determined by p1.
  VAR pos p1;
  PROC main()
    ! Aggregate type pos - determined by p1
    p1 := [1, -100, 12];
  ENDPROC
ENDMODULE

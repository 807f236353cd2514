MODULE aggregate_for_record
! @format 2
! @section 2.17
! @section 3.10
! @expect ok
! @description An aggregate is equal to a record type when its members are equal to the corresponding components.
  RECORD vector
    num x;
    num y;
    num z;
  ENDRECORD
  VAR vector v := [1, 2, 3];
  VAR pos p;
  PROC main()
    v := [4, 5, 6];
    p := [v.x, v.y, v.z];
  ENDPROC
ENDMODULE

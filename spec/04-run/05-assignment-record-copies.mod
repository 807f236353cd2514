MODULE assignment_record_copies
! @format 3
! @section 4.5
! @section 2.14
! @expect ok
! @description Records are values: after p2 := p1, changing p1.x does not change p2 (the assignment copies the value).
! @output p1.x=9
! @output p2.x=1
! @exit 0
  PROC main()
    VAR pos p1 := [1, 2, 3];
    VAR pos p2;
    p2 := p1;
    p1.x := 9;
    TPWrite "p1.x=" \Num:=p1.x;
    TPWrite "p2.x=" \Num:=p2.x;
  ENDPROC
ENDMODULE

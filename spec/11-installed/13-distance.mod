MODULE distance_use
! @format 3
! @section 13
! @expect ok
! @description Distance gives the distance between two points.
! @output 5
! @output 13
! @exit 0
  PROC main()
    VAR pos a := [1, 1, 1];
    VAR pos b := [4, 5, 1];
    VAR pos c := [4, 5, 13];
    TPWrite "" \Num:=Distance(a, b);
    TPWrite "" \Num:=Distance(a, c);
  ENDPROC
ENDMODULE

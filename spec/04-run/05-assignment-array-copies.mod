MODULE assignment_array_copies
! @format 3
! @section 4.5
! @section 2.22
! @expect ok
! @description Arrays are values: after b := a, changing a{1} does not change b{1}.
! @output a{1}=9
! @output b{1}=1
! @exit 0
  VAR num a{3} := [1, 2, 3];
  VAR num b{3};
  PROC main()
    b := a;
    a{1} := 9;
    TPWrite "a{1}=" \Num:=a{1};
    TPWrite "b{1}=" \Num:=b{1};
  ENDPROC
ENDMODULE

MODULE equality_arrays
! @format 2
! @section 3.12
! @expect ok
! @description = and <> are the only operators valid on arrays; arrays of equal type.
  VAR num a{3};
  VAR num b{3};
  VAR pos m1{2, 2};
  VAR pos m2{2, 2};
  VAR bool r;
  PROC main()
    r := a = b;
    r := m1 <> m2;
    r := a = [1, 2, 3];
  ENDPROC
ENDMODULE

MODULE array_and_scalar
! @format 2
! @section 2.17
! @expect semantic-error 9:10
! @description An array is not equal to a scalar of its element type; refused at the right-hand side.
  VAR num a{3};
  VAR num n;
  PROC main()
    n := a;
  ENDPROC
ENDMODULE

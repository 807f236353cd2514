MODULE refused_arithmetic_on_arrays
! @format 2
! @section 3.12
! @expect semantic-error 10:10
! @description = and <> are the only operators valid on arrays; + on arrays is refused at the left operand.
  VAR num a{3};
  VAR num b{3};
  VAR num r{3};
  PROC main()
    r := a + b;
  ENDPROC
ENDMODULE

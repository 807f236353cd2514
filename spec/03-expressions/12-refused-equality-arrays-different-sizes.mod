MODULE refused_equality_arrays
! @format 2
! @section 3.12
! @expect semantic-error 10:10
! @description Arrays compared with = must be of equal type; {3} and {4} are refused at the left operand.
  VAR num a{3};
  VAR num b{4};
  VAR bool r;
  PROC main()
    r := a = b;
  ENDPROC
ENDMODULE

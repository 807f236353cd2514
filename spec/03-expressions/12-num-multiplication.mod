MODULE num_multiplication
! @format 2
! @section 3.12
! @expect ok
! @description Row * num * num -> num.
  VAR num a;
  VAR num b;
  VAR num r;
  PROC main()
    r := a * b;
  ENDPROC
ENDMODULE

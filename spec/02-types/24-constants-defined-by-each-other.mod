MODULE constants_defined_by_each_other
! @format 2
! @section 3.2
! @section 2.24
! @expect semantic-error 8:18
! @description Two constants defined by each other: the values are evaluated in declaration order, and the reference that closes the cycle (the a in b's initial value) is refused.
  CONST num a := b * 2;
  CONST num b := a;
  PROC main()
  ENDPROC
ENDMODULE

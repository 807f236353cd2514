MODULE semi_value_in_value_context
! @format 2
! @section 2.17
! @expect ok
! @description Rule 3 of section 2.17: a semi-value object and its associated value type are equal in value context.
  VAR signaldi di1;
  VAR num n;
  VAR bool on;
  PROC main()
    n := di1;
    on := di1 = 1;
  ENDPROC
ENDMODULE

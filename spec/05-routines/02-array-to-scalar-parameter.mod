MODULE array_to_scalar_parameter
! @format 2
! @section 5.2
! @expect semantic-error 10:10
! @description An array argument for a scalar parameter; refused at the argument.
  VAR num values{3};
  PROC show(num x)
  ENDPROC
  PROC main()
    show values;
  ENDPROC
ENDMODULE

MODULE reference_argument_semi_value
! @format 2
! @section 2.16
! @section 5.2
! @expect ok
! @description Table of section 2.16, row argument, column semi-value: legal for a var parameter and a ref parameter.
  VAR signaldi sig1;
  VAR signaldi inputs{2};
  VAR num n;
  PROC wait_on(VAR signaldi s)
  ENDPROC
  PROC main()
    wait_on sig1;
    wait_on inputs{2};
    n := Dim(inputs, 1);
  ENDPROC
ENDMODULE

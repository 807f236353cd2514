MODULE declaration_ref_parameter
! @format 2
! @section 2.16
! @section 11
! @expect ok
! @description Table of section 2.16, row routine parameter ref (installed routines only): value, non-value and semi-value arguments are all taken by Dim and Present.
  VAR num values{4};
  VAR iodev devs{2};
  VAR signaldi inputs{3};
  VAR num n;
  PROC main()
    n := Dim(values, 1) + Dim(devs, 1) + Dim(inputs, 1);
  ENDPROC
ENDMODULE

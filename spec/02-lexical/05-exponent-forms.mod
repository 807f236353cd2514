MODULE exponent_forms
! @section 2.5
! @expect ok
! @description <exponent>: E or e, an optional sign, digits.
  VAR num x;
  PROC main()
    x := 2E6;
    x := 2e6;
    x := 2E+6;
    x := 2E-6;
    x := 1E0;
    x := 2.5e+3;
  ENDPROC
ENDMODULE

MODULE manual_examples
! @section 2.5
! @expect ok
! @description The examples of numeric literals printed in section 2.5.
  VAR num x;
  PROC main()
    x := 7990;
    x := 23.67;
    x := 2E6;
    x := .27;
    x := 2.5E-3;
    x := 38.;
  ENDPROC
ENDMODULE

MODULE fraction_forms
! @section 2.5
! @expect ok
! @description <integer> '.' [<integer>] [<exponent>] and [<integer>] '.' <integer> [<exponent>].
  VAR num x;
  PROC main()
    x := 23.67;
    x := .5;
    x := 38.;
    x := 38.E2;
    x := .5E1;
    x := 0.5;
  ENDPROC
ENDMODULE

MODULE decimal_integer
! @section 2.5
! @expect ok
! @description <decimal integer> 0D/0d followed by digits, with an optional exponent.
  VAR num x;
  PROC main()
    x := 0D123;
    x := 0d0;
    x := 0D12E3;
    x := 0d5e-1;
  ENDPROC
ENDMODULE

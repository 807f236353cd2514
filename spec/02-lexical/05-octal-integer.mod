MODULE octal_integer
! @section 2.5
! @expect ok
! @description <octal integer> 0O/0o followed by octal digits.
  VAR num x;
  PROC main()
    x := 0O17;
    x := 0o777;
    x := 0o0;
  ENDPROC
ENDMODULE

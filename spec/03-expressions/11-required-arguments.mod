MODULE required_arguments
! @format 2
! @section 3.11
! @expect ok
! @description Section 3.11: two required arguments, positional and named.
  VAR num x;
  PROC main()
    x := polar(3.937, 0.785398);
    x := polar(dist := 3.937, angle := 0.785398);
    x := polar(3.937, angle := 0.785398);
  ENDPROC

  FUNC num polar(num dist, num angle)
    RETURN dist * angle;
  ENDFUNC
ENDMODULE

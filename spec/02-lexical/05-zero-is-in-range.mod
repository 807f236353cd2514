MODULE zero_is_in_range
! @section 2.5
! @expect ok
! @description Zero is within range whatever its form.
  VAR num x;
  PROC main()
    x := 0.0;
    x := 0E5;
    x := 0X000;
    x := 0D0;
  ENDPROC
ENDMODULE

MODULE integer
! @section 2.5
! @expect ok
! @description <integer>: one or more digits, leading zeros allowed.
  VAR num x;
  PROC main()
    x := 0;
    x := 7;
    x := 0012;
    x := 8388608;
  ENDPROC
ENDMODULE

MODULE binary_integer
! @section 2.5
! @expect ok
! @description <binary integer> 0B/0b followed by binary digits.
  VAR num x;
  PROC main()
    x := 0B1010;
    x := 0b1;
    x := 0b0;
  ENDPROC
ENDMODULE

MODULE hex_integer
! @section 2.5
! @expect ok
! @description <hex integer> 0X/0x with upper and lower case hex digits; 0X1E2 is the hex number 482, not an exponent.
  VAR num x;
  PROC main()
    x := 0XFF;
    x := 0x1a2B;
    x := 0x0;
    x := 0X1E2;
  ENDPROC
ENDMODULE

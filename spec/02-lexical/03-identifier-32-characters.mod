MODULE identifier_32_characters
! @section 2.3
! @expect ok
! @description An identifier of exactly 32 characters is accepted.
  VAR num abcdefghijklmnopqrstuvwxyz_12345;
  PROC main()
    abcdefghijklmnopqrstuvwxyz_12345 := 1;
  ENDPROC
ENDMODULE

MODULE length_80_with_character_code
! @section 2.7
! @section 2.13
! @expect ok
! @description A character code is one byte of the value: 79 characters and \41 make 80 bytes.
  VAR string s;
  PROC main()
    s := "aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa\41";
  ENDPROC
ENDMODULE

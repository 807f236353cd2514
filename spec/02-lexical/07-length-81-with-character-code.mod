MODULE length_81_with_character_code
! @section 2.7
! @section 2.13
! @expect lexical-error 8:10
! @description A character code is one byte of the value: 80 characters and \41 make 81 bytes.
  VAR string s;
  PROC main()
    s := "aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa\41";
  ENDPROC
ENDMODULE

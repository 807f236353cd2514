MODULE length_41_two_byte_characters
! @section 2.7
! @section 2.13
! @expect lexical-error 8:10
! @description The limit counts bytes, not characters: 41 two-byte characters make 82 bytes.
  VAR string s;
  PROC main()
    s := "ééééééééééééééééééééééééééééééééééééééééé";
  ENDPROC
ENDMODULE

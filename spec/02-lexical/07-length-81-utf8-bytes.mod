MODULE length_81_utf8_bytes
! @section 2.7
! @section 2.13
! @expect lexical-error 8:10
! @description The limit counts UTF-8 bytes: 79 ASCII characters and one two-byte character make 81 bytes.
  VAR string s;
  PROC main()
    s := "aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaé";
  ENDPROC
ENDMODULE

MODULE length_80_utf8_bytes
! @section 2.7
! @section 2.13
! @expect ok
! @description The limit counts UTF-8 bytes: 78 ASCII characters and one two-byte character, or 40 two-byte characters, make 80 bytes.
  VAR string s;
  VAR string t;
  PROC main()
    s := "aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaé";
    t := "éééééééééééééééééééééééééééééééééééééééé";
  ENDPROC
ENDMODULE

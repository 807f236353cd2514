MODULE utf8_in_string
! @section 2.1
! @section 2.7
! @expect ok
! @description Any UTF-8 symbol, emoji included, may appear in a string literal.
  VAR string s;
  PROC main()
    s := "Größe 注释 😀";
  ENDPROC
ENDMODULE

MODULE t
! @expect-message 5:13: lexical error: illegal character ''' (§2.1)
! @expect-hint a string literal is written between double quotes: "text" (§2.7)
  PROC main()
    TPWrite 'hello';
  ENDPROC
ENDMODULE

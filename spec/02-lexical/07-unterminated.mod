MODULE unterminated
! @section 2.7
! @expect lexical-error 7:10
! @description A string literal must be closed on its line: a newline cannot be part of it.
  VAR string s;
  PROC main()
    s := "abc;
    s := "def";
  ENDPROC
ENDMODULE

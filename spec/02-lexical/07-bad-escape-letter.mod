MODULE bad_escape_letter
! @section 2.7
! @expect lexical-error 7:10
! @description A backslash must be doubled or start a two-digit character code: \x is neither.
  VAR string s;
  PROC main()
    s := "a\xb";
  ENDPROC
ENDMODULE

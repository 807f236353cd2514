MODULE backslash_before_quote
! @section 2.7
! @expect lexical-error 7:10
! @description A backslash does not escape a quote: a quote is written twice, a backslash must be doubled.
  VAR string s;
  PROC main()
    s := "a\"";
  ENDPROC
ENDMODULE

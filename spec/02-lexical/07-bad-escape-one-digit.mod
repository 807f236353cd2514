MODULE bad_escape_one_digit
! @section 2.7
! @expect lexical-error 7:10
! @description A character code needs two hex digits: \1 followed by the closing quote is not one.
  VAR string s;
  PROC main()
    s := "a\1";
  ENDPROC
ENDMODULE

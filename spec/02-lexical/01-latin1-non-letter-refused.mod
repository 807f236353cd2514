MODULE latin1_non_letter_refused
! @section 2.1
! @expect lexical-error 7:12
! @description A Latin-1 character that is neither a letter, a digit nor a delimiter (section sign) is not a token.
  VAR num x;
  PROC main()
    x := 1 § 2;
  ENDPROC
ENDMODULE

MODULE number_joined_to_reserved_word
! @section 2.2
! @expect lexical-error 7:12
! @description A numeric literal must be separated from a following reserved word.
  VAR num x;
  PROC main()
    IF x = 1THEN
      x := 2;
    ENDIF
  ENDPROC
ENDMODULE

MODULE illegal_ascii_character
! @section 2.1
! @section 2.8
! @expect lexical-error 8:12
! @description '#' is neither a letter, a digit nor a delimiter.
  VAR num x;
  PROC main()
    x := 1 # 2;
  ENDPROC
ENDMODULE

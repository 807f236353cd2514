MODULE reserved_word_joined_to_identifi
! @section 2.2
! @expect syntax-error 7:11
! @description FROM1 is one identifier, not the reserved word FROM followed by 1.
  VAR num x;
  PROC main()
    FOR i FROM1 TO 10 DO
      x := i;
    ENDFOR
  ENDPROC
ENDMODULE

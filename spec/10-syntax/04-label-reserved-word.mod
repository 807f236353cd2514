MODULE label_reserved_word
! @section 4.4
! @expect syntax-error 7:5
! @description A label is an identifier: a reserved word is not one.
  VAR num i;
  PROC main()
    DO: i := 1;
  ENDPROC
ENDMODULE

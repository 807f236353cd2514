MODULE raise_string
! @format 2
! @section 4.11
! @expect semantic-error 7:11
! @description The error number is a num; a string is refused at the expression.
  PROC main()
    RAISE "jam";
  ENDPROC
ENDMODULE

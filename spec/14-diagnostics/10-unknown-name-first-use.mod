MODULE unknown_name_first_use
! @format 2
! @section 2.20
! @expect semantic-error 8:16
! @description A misspelt data object (countr for counter) is an unknown name; the first use is the place (the hint: did you mean counter?).
  VAR num counter;
  PROC main()
    counter := countr + 1;
  ENDPROC
ENDMODULE

MODULE number_joined_to_identifier
! @section 2.2
! @expect lexical-error 7:10
! @description A numeric literal must be separated from a following identifier.
  VAR num x;
  PROC main()
    x := 12abc;
  ENDPROC
ENDMODULE

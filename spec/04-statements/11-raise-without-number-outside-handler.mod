MODULE raise_without_number_outside
! @format 2
! @section 4.11
! @expect semantic-error 7:5
! @description A RAISE without an error number may only appear in an error handler; refused at RAISE.
  PROC main()
    RAISE;
  ENDPROC
ENDMODULE

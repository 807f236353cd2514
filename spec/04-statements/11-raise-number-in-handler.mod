MODULE raise_number_in_handler
! @format 2
! @section 4.11
! @expect semantic-error 9:5
! @description A RAISE with an error number may not appear in an error handler; refused at RAISE.
  PROC main()
    DebugBreak;
  ERROR
    RAISE 12;
  ENDPROC
ENDMODULE

MODULE unknown_procedure
! @format 2
! @section 4.6
! @expect semantic-error 7:5
! @description A procedure that is neither declared nor installed; refused at its name.
  PROC main()
    spray 1;
  ENDPROC
ENDMODULE

MODULE pers_in_routine
! @format 2
! @section 2.23
! @expect semantic-error 7:5
! @description Persistents can only be declared at module level, not inside a routine; refused at PERS.
  PROC main()
    PERS num pcounter := 0;
  ENDPROC
ENDMODULE

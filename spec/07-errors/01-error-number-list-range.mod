MODULE error_number_range
! @format 2
! @section 7.2
! @expect semantic-error 8:10
! @description An error number of an ERROR list is a whole number a num holds exactly; 8234567890123456789 names no error (it overflowed the checker before).
  PROC main()
    TPWrite "x";
  ERROR (8234567890123456789)
    RETURN;
  ENDPROC
ENDMODULE

MODULE assignment_to_predefined
! @format 2
! @section 4.5
! @section 12
! @expect semantic-error 8:5
! @description The predefined ERR_ constants are constants (chapter 12); refused at the target.
  PROC main()
    ERR_DIVZERO := 3;
  ENDPROC
ENDMODULE

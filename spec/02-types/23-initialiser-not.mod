MODULE initialiser_not
! @format 2
! @section 2.23
! @section 3.3
! @expect semantic-error 7:25
! @description Only a numeric literal may carry a sign; NOT TRUE is not a literal expression; refused at NOT.
  PERS bool inactive := NOT TRUE;
ENDMODULE

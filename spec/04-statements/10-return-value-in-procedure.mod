MODULE return_value_in_procedure
! @format 2
! @section 4.10
! @expect semantic-error 7:5
! @description A RETURN in a procedure may not have a return expression; refused at RETURN.
  PROC message(string mess)
    RETURN 1;
  ENDPROC
ENDMODULE

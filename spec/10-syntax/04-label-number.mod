MODULE label_number
! @section 4.4
! @expect syntax-error 7:5
! @description A label is an identifier: a number cannot begin a statement.
  VAR num i;
  PROC main()
    10: i := 1;
  ENDPROC
ENDMODULE

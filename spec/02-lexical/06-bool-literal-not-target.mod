MODULE bool_literal_not_target
! @section 2.6
! @expect syntax-error 7:5
! @description TRUE is a literal, not a data object: it cannot begin a statement.
  VAR bool b;
  PROC main()
    TRUE := FALSE;
  ENDPROC
ENDMODULE

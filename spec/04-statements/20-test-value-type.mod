MODULE test_value_type
! @format 2
! @section 4.20
! @expect semantic-error 11:10
! @description The type of a test value must equal the type of the test expression; a string value for a num is refused at the value.
  VAR num choice;
  PROC main()
    TEST choice
    CASE 1:
      choice := 0;
    CASE "two":
      choice := 0;
    ENDTEST
  ENDPROC
ENDMODULE

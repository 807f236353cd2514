MODULE test_expression_once
! @format 3
! @section 4.20
! @expect ok
! @description The test expression is evaluated once, and its value is compared with the test values in turn (reading of section 4.20: the statement selects by "the value of the expression").
! @output evaluated
! @output three
! @exit 0
  FUNC num value()
    TPWrite "evaluated";
    RETURN 3;
  ENDFUNC
  PROC main()
    TEST value()
    CASE 1:
      TPWrite "one";
    CASE 2:
      TPWrite "two";
    CASE 3:
      TPWrite "three";
    ENDTEST
  ENDPROC
ENDMODULE

MODULE test_no_match
! @format 3
! @section 4.20
! @expect ok
! @description Without DEFAULT, a value that fits no CASE selects no statement list (section 4.20).
! @output after
! @exit 0
  VAR num choice := 9;
  PROC main()
    TEST choice
    CASE 1:
      TPWrite "one";
    CASE 2:
      TPWrite "two";
    ENDTEST
    TPWrite "after";
  ENDPROC
ENDMODULE

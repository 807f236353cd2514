MODULE test_first_match
! @format 3
! @section 4.20
! @expect ok
! @description When more than one test value fits the test expression, only the first one counts (section 4.20): 2 selects the first CASE, not the second.
! @output first
! @exit 0
  VAR num choice := 2;
  PROC main()
    TEST choice
    CASE 1, 2, 3:
      TPWrite "first";
    CASE 2:
      TPWrite "second";
    DEFAULT:
      TPWrite "default";
    ENDTEST
  ENDPROC
ENDMODULE

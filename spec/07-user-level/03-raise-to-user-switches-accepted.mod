MODULE raise_to_user_switches_accepted (NOSTEPIN)
! @format 2
! @section 7.3
! @section 2.4
! @expect ok
! @description In the error handler of a NOSTEPIN routine, RaiseToUser takes \Continue (ABB's name: CONTINUE is a reserved word, read as the argument's name here, doc/rulings.md R-7.3-m), \Resume (the manual's name, section 7.3) or \BreakOff, each with or without \ErrorNumber.
  PROC tool(num k)
    RAISE 5;
  ERROR
    TEST k
    CASE 1:
      RaiseToUser \Continue;
    CASE 2:
      RaiseToUser \Continue \ErrorNumber:=ERR_DIVZERO;
    CASE 3:
      RaiseToUser \Resume;
    DEFAULT:
      RaiseToUser \BreakOff \ErrorNumber:=6;
    ENDTEST
  ENDPROC
ENDMODULE

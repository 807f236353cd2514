MODULE test_variable_values
! @format 2
! @section 4.20
! @section 8
! @expect ok
! @description Ruling: test values may be variables, as in chapter 8's TEST INTNO CASE empty: CASE full:.
  LOCAL VAR intnum empty;
  LOCAL VAR intnum full;
  TRAP ftrap
    TEST INTNO
    CASE empty:
      DebugBreak;
    CASE full:
      DebugBreak;
    ENDTEST
    RETURN;
  ENDTRAP
ENDMODULE

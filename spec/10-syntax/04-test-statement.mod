MODULE test_statement
! @section 4.20
! @expect ok
! @description The example of section 4.20 (pick number := choice reads as a call of pick with a named argument), <CSE>, a lone DEFAULT.
  VAR num choice;
  VAR iodev console;
  PROC main()
    TEST choice
    CASE 1, 2, 3 :
      pick number := choice;
    CASE 4 :
      stand_by;
    DEFAULT:
      write console, "Illegal choice";
    ENDTEST
    TEST choice
    <CSE>
    CASE 5:
    ENDTEST
    TEST choice
    DEFAULT:
    ENDTEST
  ENDPROC
ENDMODULE

MODULE continue_argument_strict (NOSTEPIN)
! @section 7.3
! @section 2.4
! @expect syntax-error 10:18
! @options strict
! @description Under strict mode \Continue is refused at the word: CONTINUE is a reserved word (section 2.4) and cannot name an argument by chapter 10's grammar; the manual's name of the switch is \Resume (section 7.3; doc/rulings.md R-7.3-m).
  PROC tool()
    RAISE 5;
  ERROR
    RaiseToUser \Continue;
  ENDPROC
ENDMODULE

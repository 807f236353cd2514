MODULE example
! @section 7.6
! @expect ok
! @description Example 1 of section 7.6.
  PROC main()
    proc1;
  ERROR
    !Error handling
  ENDPROC
  PROC proc1()
    !Move instructions !Motion pointer
    proc2;
  ERROR
    !Error handling
  ENDPROC
  PROC proc2()
    proc3;
  ERROR
    !Error handling
  ENDPROC
  PROC proc3()
    !Non-move instructions !Program pointer
  ERROR
    !Error handling
  ENDPROC
ENDMODULE

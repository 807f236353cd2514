MODULE test_default
! @format 3
! @section 4.20
! @expect ok
! @description Section 4.20's example with choice = 4 and 7: 4 selects CASE 4, 7 fits no CASE and selects DEFAULT.
! @output stand_by
! @output Illegal choice
! @exit 0
  PROC stand_by()
    TPWrite "stand_by";
  ENDPROC
  PROC pick(num choice)
    TEST choice
    CASE 1, 2, 3:
      TPWrite "number";
    CASE 4:
      stand_by;
    DEFAULT:
      TPWrite "Illegal choice";
    ENDTEST
  ENDPROC
  PROC main()
    pick 4;
    pick 7;
  ENDPROC
ENDMODULE

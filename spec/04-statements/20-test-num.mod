MODULE test_num
! @format 2
! @section 4.20
! @expect ok
! @description Section 4.20's example: a num test expression with num test values.
  VAR num choice;
  VAR num pick_number;
  PROC main()
    TEST choice
    CASE 1, 2, 3 :
      pick_number := choice;
    CASE 4 :
      stand_by;
    DEFAULT:
      TPWrite "Illegal choice";
    ENDTEST
  ENDPROC
  PROC stand_by()
  ENDPROC
ENDMODULE

MODULE break_in_test_outside_loop
! @format 2
! @section 4.8
! @expect semantic-error 10:7
! @description A TEST is not a loop: BREAK in a CASE list outside any loop is refused at BREAK.
  VAR num reg1;
  PROC main()
    TEST reg1
    CASE 1:
      BREAK;
    ENDTEST
  ENDPROC
ENDMODULE

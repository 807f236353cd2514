MODULE break_in_compact_if_outside_loop
! @format 2
! @section 4.8
! @expect semantic-error 8:17
! @description An IF is not a loop: BREAK in a compact IF outside any loop is refused at BREAK.
  VAR num reg1;
  PROC main()
    IF reg1 > 2 BREAK;
  ENDPROC
ENDMODULE

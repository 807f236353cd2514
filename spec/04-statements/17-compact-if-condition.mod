MODULE compact_if_condition
! @format 2
! @section 4.17
! @section 3.4
! @expect semantic-error 9:8
! @description The condition of a compact IF is of type bool; a num is refused at the expression.
  VAR num counter;
  PROC main()
    IF counter + 1 counter := 0;
  ENDPROC
ENDMODULE

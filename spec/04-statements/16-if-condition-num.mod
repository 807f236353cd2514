MODULE if_condition_num
! @format 2
! @section 4.16
! @section 3.4
! @expect semantic-error 9:8
! @description A conditional expression is of type bool; a num condition is refused at the expression.
  VAR num counter;
  PROC main()
    IF counter THEN
      counter := 0;
    ENDIF
  ENDPROC
ENDMODULE

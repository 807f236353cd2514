MODULE while_condition_num
! @format 2
! @section 4.19
! @section 3.4
! @expect semantic-error 9:11
! @description A WHILE condition of type num is refused at the expression.
  VAR num a := 10;
  PROC main()
    WHILE a DO
      a := a - 1;
    ENDWHILE
  ENDPROC
ENDMODULE

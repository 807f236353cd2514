MODULE loop_variable_is_num
! @format 2
! @section 4.18
! @section 2.17
! @expect semantic-error 10:12
! @description A loop variable is of type num: assigning it to a string is refused at the right-hand side.
  VAR string s;
  PROC main()
    FOR i FROM 1 TO 3 DO
      s := i;
    ENDFOR
  ENDPROC
ENDMODULE

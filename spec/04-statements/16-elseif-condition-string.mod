MODULE elseif_condition_string
! @format 2
! @section 4.16
! @section 3.4
! @expect semantic-error 12:12
! @description An ELSEIF condition of type string is refused at the expression.
  VAR num counter;
  VAR string mode;
  PROC main()
    IF counter > 0 THEN
      counter := 0;
    ELSEIF mode THEN
      counter := 1;
    ENDIF
  ENDPROC
ENDMODULE

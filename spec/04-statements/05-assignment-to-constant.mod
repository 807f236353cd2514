MODULE assignment_to_constant
! @format 2
! @section 4.5
! @expect semantic-error 8:5
! @description A constant cannot change its value: it is no assignment target (the target is a variable, persistent or parameter); refused at the target.
  CONST num maxtemp := 39.5;
  PROC main()
    maxtemp := 40;
  ENDPROC
ENDMODULE

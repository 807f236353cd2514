MODULE refused_result_bool_to_num
! @format 2
! @section 3.12
! @section 4.5
! @expect semantic-error 11:10
! @description A comparison gives a bool; assigning it to a num is refused at the right-hand side.
  VAR num a;
  VAR num b;
  VAR num r;
  PROC main()
    r := a < b;
  ENDPROC
ENDMODULE

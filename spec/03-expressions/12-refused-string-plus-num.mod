MODULE refused_string_plus_num
! @format 2
! @section 3.12
! @expect semantic-error 9:10
! @description + concatenates two strings only; string + num is refused at the left operand.
  VAR num n;
  VAR string r;
  PROC main()
    r := "count: " + n;
  ENDPROC
ENDMODULE

MODULE refused_string_times_string
! @format 2
! @section 3.12
! @expect semantic-error 9:10
! @description * on strings is no row of the table; refused at the left operand.
  VAR string s;
  VAR string r;
  PROC main()
    r := s * s;
  ENDPROC
ENDMODULE

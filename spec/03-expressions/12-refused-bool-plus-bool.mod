MODULE refused_bool_plus_bool
! @format 2
! @section 3.12
! @expect semantic-error 9:10
! @description + on bool is no row of the table; refused at the left operand.
  VAR bool a;
  VAR bool r;
  PROC main()
    r := a + a;
  ENDPROC
ENDMODULE

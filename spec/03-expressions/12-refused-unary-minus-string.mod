MODULE refused_unary_minus_string
! @format 2
! @section 3.12
! @expect semantic-error 9:10
! @description Unary - takes num, dnum or pos; refused at the operator.
  VAR string s;
  VAR string r;
  PROC main()
    r := -s;
  ENDPROC
ENDMODULE

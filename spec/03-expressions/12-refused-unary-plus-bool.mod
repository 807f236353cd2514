MODULE refused_unary_plus_bool
! @format 2
! @section 3.12
! @expect semantic-error 9:10
! @description Unary + takes num, dnum or pos; refused at the operator.
  VAR bool b;
  VAR bool r;
  PROC main()
    r := +b;
  ENDPROC
ENDMODULE

MODULE access_constant_element_to_var
! @format 2
! @section 5.2
! @expect semantic-error 8:14
! @description Table of section 5.2, row constant (an element of a constant array), column var: illegal; refused at the argument.
  CONST num table{3} := [1, 2, 3];
  PROC main()
    take_var table{1};
  ENDPROC

  PROC take_in(num x)
  ENDPROC
  PROC take_var(VAR num x)
  ENDPROC
  PROC take_pers(PERS num x)
  ENDPROC
  PROC take_inout(INOUT num x)
  ENDPROC
ENDMODULE

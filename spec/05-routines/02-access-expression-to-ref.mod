MODULE access_expression_to_ref
! @format 2
! @section 5.2
! @section 11
! @expect semantic-error 9:18
! @description Table of section 5.2, row any other expression, column ref: Present's datobj is a ref parameter; a literal is refused at the argument.
  VAR bool b;
  PROC main()
    b := Present(1);
  ENDPROC
ENDMODULE

MODULE initialiser_nested_variable
! @format 2
! @section 2.22
! @section 3.2
! @expect semantic-error 8:37
! @description No variable at any level of a constant expression: one nested in an aggregate is refused at the variable.
  VAR num depth := 50;
  VAR pos start := [100, 2 * (100 + depth), 50];
ENDMODULE

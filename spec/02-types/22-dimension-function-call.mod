MODULE dimension_function_call
! @format 2
! @section 2.22
! @section 3.2
! @expect semantic-error 8:16
! @description A dimension may not contain a function call, even of a built-in function; refused at the call.
  CONST num base{3} := [1, 2, 3];
  VAR num copy{Dim(base, 1)};
ENDMODULE

MODULE constant_type_mismatch
! @format 2
! @section 2.24
! @expect semantic-error 6:23
! @description The constant value's type must equal the constant's type; refused at the value.
  CONST bool ready := 1;
ENDMODULE

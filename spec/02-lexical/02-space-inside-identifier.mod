MODULE space_inside_identifier
! @section 2.2
! @expect syntax-error 5:14
! @description Tokens are indivisible: "my count" is two identifiers.
  VAR num my count;
ENDMODULE

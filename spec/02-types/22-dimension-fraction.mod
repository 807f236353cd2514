MODULE dimension_fraction
! @format 2
! @section 2.22
! @expect semantic-error 6:16
! @description A dimension must be an integer; refused at the dimension 2.5.
  VAR num part{2.5};
ENDMODULE

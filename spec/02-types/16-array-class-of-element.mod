MODULE array_class_of_element
! @format 2
! @section 2.16
! @expect semantic-error 6:9
! @description An array has the value class of its elements: a constant array of a non-value type is illegal; refused at the data type name.
  CONST iodev devs{2} := <EXP>;
ENDMODULE

MODULE array_parameter_element_type
! @format 2
! @section 5.2
! @expect semantic-error 10:12
! @description An array of strings for a num{*} parameter; refused at the argument.
  VAR string names{3};
  PROC arrmul(VAR num array{*}, num factor)
  ENDPROC
  PROC main()
    arrmul names, 2;
  ENDPROC
ENDMODULE

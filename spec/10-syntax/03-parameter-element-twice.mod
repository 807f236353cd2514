MODULE parameter_element_twice
! @section 3.9
! @expect syntax-error 6:11
! @description A parameter element is indexed once, with an index list.
  PROC p(VAR num arr{*, *})
    arr{1}{2} := 0;
  ENDPROC
ENDMODULE

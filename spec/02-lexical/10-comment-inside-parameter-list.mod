MODULE comment_inside_parameter_list
! @section 2.10
! @expect syntax-error 5:17
! @description A comment is not white space: it cannot stand inside a parameter list.
  PROC p(num a, ! first
         num b)
  ENDPROC
ENDMODULE

MODULE comment_inside_declaration
! @section 2.10
! @expect syntax-error 5:13
! @description A comment is not white space: it cannot stand inside a data declaration.
  VAR num x ! no
    := 1;
ENDMODULE

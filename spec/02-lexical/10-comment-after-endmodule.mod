MODULE comment_after_endmodule
! @section 2.10
! @section 9.2
! @expect syntax-error 8:1
! @description A comment is an element of a list inside the module: it cannot follow ENDMODULE.
  VAR num x;
ENDMODULE
! nothing may follow ENDMODULE

! nothing may precede MODULE
MODULE comment_before_module
! @section 2.10
! @section 9.2
! @expect syntax-error 1:1
! @description A comment is an element of a list inside the module: it cannot precede MODULE.
  VAR num x;
ENDMODULE

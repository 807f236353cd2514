! nothing may precede MODULE
MODULE comment_before_module_strict
! @section 2.10
! @section 9.2
! @expect syntax-error 1:1
! @options strict
! @description In strict mode a comment is an element of a list inside the module: it cannot precede MODULE.
  VAR num x;
ENDMODULE

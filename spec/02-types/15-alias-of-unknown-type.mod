MODULE alias_of_unknown_type
! @format 2
! @section 2.15
! @expect semantic-error 6:9
! @description An alias of a type that is not known is refused at the base type name.
  ALIAS gizmo widget;
ENDMODULE

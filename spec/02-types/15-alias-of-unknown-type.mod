MODULE alias_of_unknown_type
! @format 2
! @section 2.15
! @section 2.11
! @expect semantic-error 7:9
! @description An alias of a type that is not known is refused at the base type name.
  ALIAS gizmo widget;
ENDMODULE

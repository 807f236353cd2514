MODULE return_alias_types
! @format 2
! @section 4.10
! @section 2.17
! @expect ok
! @description A return expression of an equal type through an alias.
  ALIAS num level;
  FUNC level low()
    RETURN 2.5;
  ENDFUNC
  FUNC num base()
    VAR level l := 1;
    RETURN l;
  ENDFUNC
ENDMODULE

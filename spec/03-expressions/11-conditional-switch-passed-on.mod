MODULE conditional_switch_passed_on
! @format 2
! @section 3.11
! @expect ok
! @description A switch parameter is passed on with the conditional syntax.
  FUNC num cosine_of(num a \switch rad)
    RETURN cosine(a \rad ? rad);
  ENDFUNC

  FUNC num cosine(num angle \switch rad)
    IF Present(rad) RETURN angle;
    RETURN angle / 57.29578;
  ENDFUNC
ENDMODULE

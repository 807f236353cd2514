MODULE function_without_return
! @format 2
! @section 5.5
! @section 12
! @expect ok
! @description A function whose evaluation may end without RETURN is an execution error (ERR_FNCNORET), not a static one.
  FUNC num maybe(num x)
    IF x > 0 RETURN x;
  ENDFUNC
ENDMODULE

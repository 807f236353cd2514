MODULE placeholder_exp
! @section 2.9
! @section 3.1
! @expect ok
! @description <EXP> stands for an <expression>: initial value, dimension, condition, argument, late-bound name, return value.
  VAR num x{<EXP>} := <EXP>;
  FUNC num f()
    IF <EXP> THEN
      x{1} := <EXP>;
    ENDIF
    p <EXP>, name := <EXP>;
    % <EXP> %;
    RETURN <EXP>;
  ENDFUNC
ENDMODULE

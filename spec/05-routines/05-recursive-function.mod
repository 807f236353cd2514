MODULE recursive_function
! @format 2
! @section 5.5
! @section 2.21
! @expect ok
! @description A function may call itself (section 2.21: each recursive instance has its own routine variables).
  FUNC num factorial(num n)
    VAR num result;
    IF n <= 1 RETURN 1;
    result := n * factorial(n - 1);
    RETURN result;
  ENDFUNC
ENDMODULE

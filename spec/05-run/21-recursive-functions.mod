MODULE recursive_functions
! @format 3
! @section 2.21
! @section 5.5
! @expect ok
! @description Recursive functions, each call with its own parameters: factorial and Fibonacci.
! @output 5!=120
! @output fib(15)=610
! @exit 0
  FUNC num fact(num n)
    IF n <= 1 RETURN 1;
    RETURN n * fact(n - 1);
  ENDFUNC
  FUNC num fib(num n)
    IF n < 2 RETURN n;
    RETURN fib(n - 1) + fib(n - 2);
  ENDFUNC
  PROC main()
    TPWrite "5!=" \Num:=fact(5);
    TPWrite "fib(15)=" \Num:=fib(15);
  ENDPROC
ENDMODULE

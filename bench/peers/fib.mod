MODULE bench_fib
  ! fib(25), recursive, on num.
  FUNC num fib(num n)
    IF n < 2 RETURN n;
    RETURN fib(n - 1) + fib(n - 2);
  ENDFUNC

  PROC main()
    TPWrite "fib(25)=" \Num:=fib(25);
  ENDPROC
ENDMODULE

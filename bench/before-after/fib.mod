MODULE BaFib
  ! Recursive fib: calls, IN num parameters, RETURN (bench/before-after.sh).
  FUNC num fib(num n)
    IF n < 2 RETURN n;
    RETURN fib(n - 1) + fib(n - 2);
  ENDFUNC

  PROC main()
    VAR num r;
    r := fib(30);
    TPWrite "fib(30)=" \Num:=r;
  ENDPROC
ENDMODULE

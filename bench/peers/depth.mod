MODULE bench_depth
  ! Recursion to depth 9,000, a hundred times.
  FUNC num depth(num n)
    IF n = 0 RETURN 0;
    RETURN depth(n - 1) + 1;
  ENDFUNC

  PROC main()
    VAR num total := 0;
    FOR r FROM 1 TO 100 DO
      total := total + depth(9000);
    ENDFOR
    TPWrite "total=" \Num:=total;
  ENDPROC
ENDMODULE

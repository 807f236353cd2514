MODULE bench_dnumloop
  ! A loop of 1,000,000 iterations on dnum: a counter and a sum.
  PROC main()
    VAR dnum i := 0;
    VAR dnum s := 0;
    WHILE i < 1000000 DO
      s := s + i;
      i := i + 1;
    ENDWHILE
    TPWrite "sum=" \Dnum:=s;
  ENDPROC
ENDMODULE

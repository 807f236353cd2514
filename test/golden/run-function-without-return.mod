MODULE run_function_without_return
  FUNC num half(num x)
    IF x > 0 RETURN x / 2;
  ENDFUNC
  PROC main()
    TPWrite "half=" \Num:=half(4);
    TPWrite "half=" \Num:=half(-4);
  ENDPROC
ENDMODULE

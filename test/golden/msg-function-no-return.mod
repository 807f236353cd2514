MODULE msg_function_no_return
  FUNC num Sign(num x)
    IF x > 0 THEN
      RETURN 1;
    ELSEIF x < 0 THEN
      RETURN -1;
    ENDIF
  ENDFUNC
  PROC main()
    TPWrite "s" \Num:=Sign(0);
  ENDPROC
ENDMODULE

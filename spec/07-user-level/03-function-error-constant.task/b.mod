MODULE tools (NOSTEPIN)
  FUNC num Scaled(num x)
    IF factor = 0 RAISE 5;
    RETURN x * factor;
  ERROR
    RaiseToUser \Continue \ErrorNumber:=ERR_ARGVALERR;
  ENDFUNC
ENDMODULE

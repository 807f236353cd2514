MODULE settings
  RECORD gripdata
    num force;
    num width;
  ENDRECORD
  VAR num speed_factor := 1;
  PROC report(string message)
    TPWrite message;
  ENDPROC
  FUNC num scaled(num x)
    RETURN x * speed_factor;
  ENDFUNC
ENDMODULE

MODULE settings
  LOCAL RECORD gripdata
    num force;
  ENDRECORD
ENDMODULE

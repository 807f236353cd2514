MODULE cell
  VAR num gripdata;
ENDMODULE

MODULE cell
  PROC palletizer()
  ENDPROC
ENDMODULE

MODULE tools (NOSTEPIN)
  PROC tool()
    helper;
  ENDPROC
  PROC helper()
    RAISE 56;
  ENDPROC
ENDMODULE

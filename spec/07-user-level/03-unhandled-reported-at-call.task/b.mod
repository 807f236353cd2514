MODULE tools (NOSTEPIN)
  PROC tool(num d)
    helper d;
  ENDPROC
  PROC helper(num d)
    VAR num x;
    x := 1 / d;
  ENDPROC
ENDMODULE

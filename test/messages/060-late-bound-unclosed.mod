MODULE t
! @expect-message 4:19: syntax error: expected '%' to close the late-bound procedure name (§4.6); found ';'
  PROC main()
    %"proc" + name;
  ENDPROC
ENDMODULE

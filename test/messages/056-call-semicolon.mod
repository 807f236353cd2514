MODULE t
! @expect-message 5:5: syntax error: expected an operator, or what follows the expression such as ';' (§3.1, §4.2); comments are list elements only (§2.10); found the identifier Stop
  PROC main()
    MoveL p1, v100
    Stop;
  ENDPROC
ENDMODULE

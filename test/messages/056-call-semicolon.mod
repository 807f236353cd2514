MODULE t
! @expect-message 6:5: syntax error: expected an operator, or what follows the expression such as ';' (§3.1, §4.2); comments are list elements only (§2.10); found the identifier Stop
! @expect-hint ';' is missing at the end of line 5: a simple statement and a declaration end with ';' (§4.3, §2.18)
  PROC main()
    MoveL p1, v100
    Stop;
  ENDPROC
ENDMODULE

MODULE t
! @expect-message 6:5: syntax error: expected an operator, or what follows the expression such as ';' (§3.1, §4.2); comments are list elements only (§2.10); found the identifier MoveL
! @expect-hint ';' is missing at the end of line 5: a simple statement and a declaration end with ';' (§4.3, §2.18)
  PROC main()
    MoveL p10, v100, z10, tool0
    MoveL p20, v100, fine, tool0;
  ENDPROC
ENDMODULE

MODULE t
! @expect-message 4:23: syntax error: expected ':=' or '?' after the argument's name, or ',' or ')' (§3.11); found the numeric literal 2
  PROC main()
    x := Round(y \Dec 2);
  ENDPROC
ENDMODULE

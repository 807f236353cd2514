MODULE t
! @expect-message 5:7: syntax error: expected DO after the WHILE condition (§4.19); found the identifier x
  PROC main()
    WHILE x < 10
      x := x + 1;
    ENDWHILE
  ENDPROC
ENDMODULE

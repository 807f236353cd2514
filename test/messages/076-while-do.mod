MODULE t
! @expect-message 6:7: syntax error: expected DO after the WHILE condition (§4.19); found the identifier x
! @expect-hint the WHILE at line 5 has no DO after its condition (§4.19)
  PROC main()
    WHILE x < 10
      x := x + 1;
    ENDWHILE
  ENDPROC
ENDMODULE

MODULE comment_tab_and_bang
! @section 2.10
! @expect ok
! @description <comment> ::= '!' { <character> | <tab> } <newline>: tabs, bangs, quotes and backslashes are comment text.
  VAR num x;
  PROC main()
    !	tab inside ! and another bang ! "quote" \ backslash
    x := 1;
  ENDPROC
ENDMODULE

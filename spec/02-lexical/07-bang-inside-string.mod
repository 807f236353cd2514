MODULE bang_inside_string
! @section 2.7
! @section 2.10
! @expect ok
! @description An exclamation mark inside a string literal does not begin a comment.
  VAR string s;
  PROC main()
    s := "not ! a comment";
  ENDPROC
ENDMODULE

MODULE comment_inside_compact_if
! @section 2.10
! @section 4.17
! @expect syntax-error 8:10
! @description A comment is not a simple statement: it cannot be the statement of a compact IF.
  VAR bool b;
  PROC main()
    IF b ! a comment is not a simple statement
      b := FALSE;
  ENDPROC
ENDMODULE

MODULE comment_inside_expression
! @section 2.10
! @expect syntax-error 7:14
! @description A comment is not white space: it cannot stand inside an expression.
  VAR num x;
  PROC main()
    x := 1 + ! one
         2;
  ENDPROC
ENDMODULE

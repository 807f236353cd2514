MODULE placeholder_var_misplaced
! @section 2.9
! @expect syntax-error 7:10
! @description <VAR> cannot stand as a primary of an expression.
  VAR num x;
  PROC main()
    x := <VAR> + 1;
  ENDPROC
ENDMODULE

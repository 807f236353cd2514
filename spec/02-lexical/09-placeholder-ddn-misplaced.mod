MODULE placeholder_ddn_misplaced
! @section 2.9
! @expect syntax-error 8:5
! @description <DDN> is a data declaration: it cannot follow a statement.
  VAR num x;
  PROC main()
    x := 1;
    <DDN>
  ENDPROC
ENDMODULE

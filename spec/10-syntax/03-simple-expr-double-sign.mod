MODULE simple_expr_double_sign
! @section 3.1
! @expect syntax-error 12:11
! @description A <simple expr> has at most one leading sign.
  VAR num a;
  VAR num b;
  VAR num c;
  VAR num d;
  VAR num e;
  VAR num x;
  PROC main()
    x := --a;
  ENDPROC
ENDMODULE

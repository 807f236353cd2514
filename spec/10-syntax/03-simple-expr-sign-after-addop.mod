MODULE simple_expr_sign_after_addop
! @section 3.1
! @expect syntax-error 12:14
! @description A sign heads a <simple expr> only: a + -b is not derivable.
  VAR num a;
  VAR num b;
  VAR num c;
  VAR num d;
  VAR num e;
  VAR num x;
  PROC main()
    x := a + -b;
  ENDPROC
ENDMODULE

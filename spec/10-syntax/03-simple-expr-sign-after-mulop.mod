MODULE simple_expr_sign_after_mulop
! @section 3.1
! @expect syntax-error 12:14
! @description A sign heads a <simple expr> only: x * -1 is not derivable (x * (-1) is).
  VAR num a;
  VAR num b;
  VAR num c;
  VAR num d;
  VAR num e;
  VAR num x;
  PROC main()
    x := a * -1;
  ENDPROC
ENDMODULE

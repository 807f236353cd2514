MODULE simple_expr_sign_after_relop
! @section 3.1
! @expect ok
! @description Each side of a relation is a <simple expr>, so each may begin with a sign: a = -1.
  VAR num a;
  VAR num b;
  VAR bool x;
  PROC main()
    x := a = -1;
    x := a < -b;
  ENDPROC
ENDMODULE

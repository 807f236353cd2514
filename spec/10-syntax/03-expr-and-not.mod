MODULE expr_and_not
! @section 3.1
! @expect syntax-error 11:16
! @description NOT heads an <expr> only: a AND NOT b is not derivable (a AND (NOT b) is).
  VAR bool a;
  VAR bool b;
  VAR bool c;
  VAR bool d;
  VAR bool x;
  PROC main()
    x := a AND NOT b;
  ENDPROC
ENDMODULE

MODULE expr_or_not
! @section 3.1
! @expect syntax-error 11:15
! @description NOT heads an <expr> only: a OR NOT b is not derivable.
  VAR bool a;
  VAR bool b;
  VAR bool c;
  VAR bool d;
  VAR bool x;
  PROC main()
    x := a OR NOT b;
  ENDPROC
ENDMODULE

MODULE expr_not_not
! @section 3.1
! @expect syntax-error 11:14
! @description NOT heads an <expr> and is followed by a <logical term>: NOT NOT a is not derivable.
  VAR bool a;
  VAR bool b;
  VAR bool c;
  VAR bool d;
  VAR bool x;
  PROC main()
    x := NOT NOT a;
  ENDPROC
ENDMODULE

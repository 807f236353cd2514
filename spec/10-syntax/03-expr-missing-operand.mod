MODULE expr_missing_operand
! @section 3.1
! @expect syntax-error 11:15
! @description OR needs a right operand.
  VAR bool a;
  VAR bool b;
  VAR bool c;
  VAR bool d;
  VAR bool x;
  PROC main()
    x := a OR ;
  ENDPROC
ENDMODULE

MODULE relation_chained_equal
! @section 3.1
! @expect syntax-error 10:16
! @description A relation has at most one relational operator, = included.
  VAR bool a;
  VAR bool b;
  VAR bool c;
  VAR bool x;
  PROC main()
    x := a = b = c;
  ENDPROC
ENDMODULE

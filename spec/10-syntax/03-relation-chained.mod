MODULE relation_chained
! @section 3.1
! @expect syntax-error 10:16
! @description A relation has at most one relational operator: relations do not chain.
  VAR num a;
  VAR num b;
  VAR num c;
  VAR bool x;
  PROC main()
    x := a < b < c;
  ENDPROC
ENDMODULE

MODULE term_missing_operand
! @section 3.1
! @expect syntax-error 12:16
! @description DIV needs a right operand.
  VAR num a;
  VAR num b;
  VAR num c;
  VAR num d;
  VAR num e;
  VAR num x;
  PROC main()
    x := a DIV ;
  ENDPROC
ENDMODULE

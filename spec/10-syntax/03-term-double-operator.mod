MODULE term_double_operator
! @section 3.1
! @expect syntax-error 12:14
! @description Two multiplying operators cannot follow each other.
  VAR num a;
  VAR num b;
  VAR num c;
  VAR num d;
  VAR num e;
  VAR num x;
  PROC main()
    x := a * / b;
  ENDPROC
ENDMODULE

MODULE expression_empty
! @section 3.1
! @expect syntax-error 12:10
! @description An assignment needs an expression after ':='.
  VAR num a;
  VAR num b;
  VAR num c;
  VAR num d;
  VAR num e;
  VAR num x;
  PROC main()
    x := ;
  ENDPROC
ENDMODULE

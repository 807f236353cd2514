MODULE logical_term_double_and
! @section 3.1
! @expect syntax-error 11:16
! @description AND needs a relation on each side.
  VAR bool a;
  VAR bool b;
  VAR bool c;
  VAR bool d;
  VAR bool x;
  PROC main()
    x := a AND AND b;
  ENDPROC
ENDMODULE

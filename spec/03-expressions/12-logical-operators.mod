MODULE logical_operators
! @format 2
! @section 3.12
! @expect ok
! @description Rows AND, XOR, OR bool, bool -> bool and NOT bool -> bool.
  VAR bool a;
  VAR bool b;
  VAR bool r;
  PROC main()
    r := a AND b;
    r := a XOR b;
    r := a OR b;
    r := NOT a;
    r := a AND (NOT b);
  ENDPROC
ENDMODULE

MODULE procedure_declaration
! @section 5.4
! @section 6.2
! @section 7.2
! @expect ok
! @description <procedure declaration> with its optional BACKWARD, ERROR (with and without an error number list) and UNDO parts.
  PROC p1()
  ENDPROC
  PROC p2(num a)
    VAR num x;
    ! comment in the data declaration list
    CONST num y := 1;
    x := a + y;
  BACKWARD
    x := 0;
  ERROR (56, ERR_DIVZERO)
    RETRY;
  UNDO
    x := 0;
  ENDPROC
  PROC p3()
  ERROR
  ENDPROC
  PROC p4()
  UNDO
  ENDPROC
  PROC p5()
  BACKWARD
  UNDO
  ENDPROC
ENDMODULE

MODULE error_number_list
! @section 7.2
! @expect ok
! @description <error number list>: num literals, entire constants, variables and persistents.
  CONST errnum escape1 := 10;
  VAR errnum myerr := 11;
  PERS errnum perr := 12;
  PROC p1()
  ERROR (56, ERR_DIVZERO)
    RETRY;
  ENDPROC
  PROC p2()
  ERROR (LONG_JMP_ALL_ERR)
    TRYNEXT;
  ENDPROC
  PROC p3()
  ERROR (escape1, myerr, perr, 0x10)
    RETURN;
  ENDPROC
ENDMODULE

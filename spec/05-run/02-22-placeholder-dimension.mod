MODULE placeholder_dimension
! @format 3
! @section 2.22
! @expect ok
! @description R-2.22-w: a placeholder for an array dimension of routine data is executed when the routine is entered (ERR_EXECPHR): the data object has no shape. As for a placeholder in an initial value (R-7.1-w), the error is raised at the call, and the caller's handler goes on with TRYNEXT.
! @output handled TRUE
! @output after
! @exit 0
  PROC sub()
    VAR num a{<EXP>};
    a{1} := 2;
    TPWrite "wrong: sub body";
  ENDPROC
  PROC main()
    sub;
    TPWrite "after";
  ERROR
    TPWrite "handled " \Bool:=ERRNO = ERR_EXECPHR;
    TRYNEXT;
  ENDPROC
ENDMODULE

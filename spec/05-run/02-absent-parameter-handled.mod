MODULE absent_parameter_handled
! @format 3
! @section 5.2
! @section 7.1
! @expect ok
! @description ERR_NOTPRES can be handled in the routine's own error handler, which may substitute a default.
! @output notpres=TRUE
! @output x=10
! @exit 0
  PROC show(\num n)
    VAR num x;
    x := n;
    TPWrite "x=" \Num:=x;
  ERROR
    TPWrite "notpres=" \Bool:=ERRNO = ERR_NOTPRES;
    x := 10;
    TRYNEXT;
  ENDPROC
  PROC main()
    show;
  ENDPROC
ENDMODULE

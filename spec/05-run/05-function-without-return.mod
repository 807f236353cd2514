MODULE function_without_return
! @format 3
! @section 5.5
! @section 12
! @expect ok
! @description A function must end with RETURN (section 5.5): reaching ENDFUNC raises ERR_FNCNORET (chapter 12), here handled by the caller, whose TRYNEXT skips the assignment.
! @output in f
! @output fncnoret=TRUE
! @output x=1
! @exit 0
  FUNC num f()
    TPWrite "in f";
  ENDFUNC
  PROC main()
    VAR num x := 1;
    x := f();
    TPWrite "x=" \Num:=x;
  ERROR
    TPWrite "fncnoret=" \Bool:=ERRNO = ERR_FNCNORET;
    TRYNEXT;
  ENDPROC
ENDMODULE

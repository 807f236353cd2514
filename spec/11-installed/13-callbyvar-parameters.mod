MODULE callbyvar_parameters
! @format 3
! @section 13
! @section 4.6
! @expect ok
! @description CallByVar passes no arguments: a procedure Name+Number that requires a parameter cannot be called that way, and the call fails with ERR_CALLPROC, as a late-bound call with arguments that do not fit (reading of chapter 12's "procedure call error at run time").
! @output callproc=TRUE
! @exit 0
  PROC proc2(num n)
    TPWrite "wrong";
  ENDPROC
  PROC main()
    CallByVar "proc", 2;
  ERROR
    TPWrite "callproc=" \Bool:=ERRNO = ERR_CALLPROC;
    RETURN;
  ENDPROC
ENDMODULE

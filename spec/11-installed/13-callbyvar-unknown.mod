MODULE callbyvar_unknown
! @format 3
! @section 13
! @section 4.6
! @expect ok
! @description CallByVar binds the name when it runs, as a late-bound call does (section 4.6): when no procedure Name+Number exists the error is ERR_REFUNKPRC, here handled.
! @output refunkprc=TRUE
! @output after
! @exit 0
  PROC proc1()
    TPWrite "proc1";
  ENDPROC
  PROC main()
    CallByVar "proc", 9;
    TPWrite "after";
  ERROR
    TPWrite "refunkprc=" \Bool:=ERRNO = ERR_REFUNKPRC;
    TRYNEXT;
  ENDPROC
ENDMODULE

MODULE placeholder_handled
! @format 3
! @section 1.2
! @section 7.1
! @expect ok
! @description ERR_EXECPHR is an ordinary execution error: the error handler sees it in ERRNO and TRYNEXT resumes after the placeholder.
! @output execphr=TRUE
! @output after
! @exit 0
  PROC main()
    <SMT>
    TPWrite "after";
  ERROR
    TPWrite "execphr=" \Bool:=ERRNO = ERR_EXECPHR;
    TRYNEXT;
  ENDPROC
ENDMODULE

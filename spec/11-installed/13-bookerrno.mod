MODULE bookerrno_use
! @format 3
! @section 13
! @section 7.1
! @expect ok
! @description BookErrNo gives an errnum variable a new error number, unused so far (installed-facts.md section 2: BookErrNo ERR_GLUEFLOW); RAISE accepts a booked number and the handler recognises it in ERRNO.
! @output distinct=TRUE
! @output glueflow=TRUE
! @output after
! @exit 0
  VAR errnum ERR_GLUEFLOW := -1;
  VAR errnum ERR_OTHER := -1;
  PROC main()
    BookErrNo ERR_GLUEFLOW;
    BookErrNo ERR_OTHER;
    TPWrite "distinct=" \Bool:=ERR_GLUEFLOW <> ERR_OTHER;
    RAISE ERR_GLUEFLOW;
    TPWrite "after";
  ERROR
    TPWrite "glueflow=" \Bool:=ERRNO = ERR_GLUEFLOW;
    TRYNEXT;
  ENDPROC
ENDMODULE

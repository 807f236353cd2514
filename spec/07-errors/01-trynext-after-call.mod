MODULE trynext_after_call
! @format 3
! @section 4.14
! @section 7.1
! @expect ok
! @description An error raised in a called procedure without error handler is raised again at the call; the caller's TRYNEXT continues after the call, so the rest of the procedure is not run.
! @output in p
! @output handler
! @output after p
! @exit 0
  PROC p()
    TPWrite "in p";
    RAISE 12;
    TPWrite "wrong";
  ENDPROC
  PROC main()
    p;
    TPWrite "after p";
  ERROR
    TPWrite "handler";
    TRYNEXT;
  ENDPROC
ENDMODULE

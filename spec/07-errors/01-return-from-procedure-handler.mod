MODULE return_from_procedure_handler
! @format 3
! @section 7.1
! @section 4.10
! @expect ok
! @description RETURN in a procedure's error handler gives control back to the caller (section 7.1), which continues after the call as after a normal return.
! @output in p
! @output p handler
! @output back in main
! @exit 0
  PROC p()
    TPWrite "in p";
    RAISE 5;
    TPWrite "wrong";
  ERROR
    TPWrite "p handler";
    RETURN;
  ENDPROC
  PROC main()
    p;
    TPWrite "back in main";
  ERROR
    TPWrite "wrong main handler";
  ENDPROC
ENDMODULE

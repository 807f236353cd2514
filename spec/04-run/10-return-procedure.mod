MODULE return_procedure
! @format 3
! @section 4.10
! @expect ok
! @description RETURN ends the procedure at once (section 4.10); the caller continues after the call.
! @output before
! @output back in main
! @exit 0
  PROC message()
    TPWrite "before";
    RETURN;
    TPWrite "wrong";
  ENDPROC
  PROC main()
    message;
    TPWrite "back in main";
  ENDPROC
ENDMODULE

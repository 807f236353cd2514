MODULE waitdi_timeflag
! @format 3
! @section 13
! @expect ok
! @io io/basic.io
! @statement-time 0
! @description WaitDI \MaxTime \TimeFlag: a timeout sets the flag TRUE and execution goes on; a wait that ends in time sets it FALSE. ERR_WAIT_MAXTIME without \TimeFlag can be handled and retried.
! @output timed out TRUE
! @output after 500
! @output timed out FALSE
! @output after 1000
! @output handled TRUE
! @output after 1500
  VAR clock c;
  VAR bool late;
  PROC main()
    ClkStart c;
    WaitDI di1, 1 \MaxTime:=0.5 \TimeFlag:=late;
    TPWrite "timed out " \Bool:=late;
    TPWrite "after " \Num:=Round(ClkRead(c) * 1000);
    WaitDI di1, 1 \MaxTime:=0.75 \TimeFlag:=late;
    TPWrite "timed out " \Bool:=late;
    TPWrite "after " \Num:=Round(ClkRead(c) * 1000);
    WaitDI di2, 0 \MaxTime:=0.5;
    TPWrite "not reached";
  ERROR
    TPWrite "handled " \Bool:=(ERRNO = ERR_WAIT_MAXTIME);
    TPWrite "after " \Num:=Round(ClkRead(c) * 1000);
    RETURN;
  ENDPROC
ENDMODULE

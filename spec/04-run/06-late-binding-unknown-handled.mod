MODULE late_binding_unknown_handled
! @format 3
! @section 4.6
! @section 7.1
! @expect ok
! @description ERR_REFUNKPRC can be handled: the handler sees it in ERRNO and TRYNEXT continues after the late-bound call.
! @output refunkprc=TRUE
! @output after
! @exit 0
  PROC main()
    % "no_such_proc" %;
    TPWrite "after";
  ERROR
    TPWrite "refunkprc=" \Bool:=ERRNO = ERR_REFUNKPRC;
    TRYNEXT;
  ENDPROC
ENDMODULE

MODULE exit_in_procedure
! @format 3
! @section 4.12
! @expect ok
! @description EXIT in a called procedure ends the whole task, not just the procedure (section 4.12): the caller does not continue.
! @output in proc
! @exit 0
  PROC stop_here()
    TPWrite "in proc";
    EXIT;
    TPWrite "wrong 1";
  ENDPROC
  PROC main()
    stop_here;
    TPWrite "wrong 2";
  ENDPROC
ENDMODULE

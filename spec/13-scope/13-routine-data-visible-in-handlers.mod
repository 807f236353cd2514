MODULE routine_data_visible_in_handlers
! @format 2
! @section 7.1
! @section 2.20
! @expect ok
! @description Routine data objects and parameters are in scope in the routine's error handler (section 7.1) and in its backward and UNDO handlers.
  PROC work(\num attempts)
    VAR num tries;
    tries := tries + 1;
  BACKWARD
    tries := 0;
  ERROR
    IF Present(attempts) tries := attempts;
    IF tries < 3 RETRY;
  UNDO
    tries := 0;
  ENDPROC
ENDMODULE

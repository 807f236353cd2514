MODULE return_forms
! @format 2
! @section 4.10
! @expect ok
! @description Section 4.10's abs_value and message, RETURN in a trap, and RETURN in error handlers.
  FUNC num abs_value(num value)
    IF value < 0 THEN
      RETURN -value;
    ELSE
      RETURN value;
    ENDIF
  ERROR
    RETURN 0;
  ENDFUNC
  PROC message(string mess)
    TPWrite mess;
    RETURN;
  ERROR
    RETURN;
  ENDPROC
  TRAP on_event
    RETURN;
  ENDTRAP
ENDMODULE

MODULE return_statement
! @section 4.10
! @expect ok
! @description The example of section 4.10.
  VAR iodev printer;
  FUNC num abs_value (num value)
    IF value < 0 THEN
      RETURN -value;
    ELSE
      RETURN value;
    ENDIF
  ENDFUNC

  PROC message ( string mess )
    write printer, mess;
    RETURN; ! could have been left out
  ENDPROC
ENDMODULE

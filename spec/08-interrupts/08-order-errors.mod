MODULE order_errors
! @format 3
! @section 8
! @section 12
! @expect ok
! @io io/edges.io
! @statement-time 0
! @description Ordering an interrupt on a number that is not connected raises ERR_UNKINO (chapter 12, "unknown interrupt number"), as does ISleep of one; a TriggValue other than 0, 1 or 2 and a timer of no time raise ERR_ARGVALERR; IDelete of a number that is not connected does nothing (doc/rulings.md R-8-f).
! @output ITimer ERR_UNKINO
! @output ISleep ERR_UNKINO
! @output ISignalDI ERR_ARGVALERR
! @output ITimer ERR_ARGVALERR
! @output end
  VAR intnum never;
  VAR intnum i1;
  VAR string what;
  TRAP t
  ENDTRAP
  PROC main()
    IDelete never;
    what := "ITimer";
    ITimer 1, never;
    what := "ISleep";
    ISleep never;
    CONNECT i1 WITH t;
    what := "ISignalDI";
    ISignalDI di1, 3, i1;
    what := "ITimer";
    ITimer 0, i1;
    TPWrite "end";
  ERROR
    IF ERRNO = ERR_UNKINO THEN
      TPWrite what + " ERR_UNKINO";
    ELSEIF ERRNO = ERR_ARGVALERR THEN
      TPWrite what + " ERR_ARGVALERR";
    ENDIF
    TRYNEXT;
  ENDPROC
ENDMODULE

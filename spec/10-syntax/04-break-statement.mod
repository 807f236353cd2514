MODULE break_statement
! @section 4.8
! @expect ok
! @description The example of section 4.8 (its comment, wrapped in print, joined into one line).
  VAR num reg1;
  PROC main()
    WHILE (TRUE) DO
      TPWrite "Start WHILE";
      Incr reg1;
      IF (reg1 > 2) THEN
        BREAK; ! For reg1 > 2 the execution will continue after the While loop
      ENDIF
    ENDWHILE
  ENDPROC
ENDMODULE

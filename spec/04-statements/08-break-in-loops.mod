MODULE break_in_loops
! @format 2
! @section 4.8
! @expect ok
! @description Section 4.8's example, and BREAK in FOR, inside IF, TEST and compact IF within loops.
  VAR num reg1;
  PROC main()
    WHILE (TRUE) DO
      TPWrite "Start WHILE";
      reg1 := reg1 + 1;
      IF (reg1 > 2) THEN
        BREAK;
      ENDIF
    ENDWHILE
    FOR i FROM 1 TO 10 DO
      IF i = 5 BREAK;
      TEST i
      CASE 7:
        BREAK;
      ENDTEST
    ENDFOR
  ENDPROC
ENDMODULE

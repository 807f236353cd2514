MODULE break_while
! @format 3
! @section 4.8
! @expect ok
! @description Section 4.8's example: BREAK ends the WHILE (TRUE) loop when reg1 > 2; execution continues after ENDWHILE.
! @output Start WHILE
! @output Start WHILE
! @output Start WHILE
! @output after reg1=3
! @exit 0
  VAR num reg1;
  PROC main()
    WHILE (TRUE) DO
      TPWrite "Start WHILE";
      Incr reg1;
      IF (reg1 > 2) THEN
        BREAK;
      ENDIF
    ENDWHILE
    TPWrite "after reg1=" \Num:=reg1;
  ENDPROC
ENDMODULE

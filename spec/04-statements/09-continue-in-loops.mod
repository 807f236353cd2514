MODULE continue_in_loops
! @format 2
! @section 4.9
! @expect ok
! @description Section 4.9's example, and CONTINUE in a WHILE loop.
  VAR num n;
  PROC main()
    FOR i FROM 1 TO 5 DO
      TPWrite "ABC";
      IF ( i > 3) THEN
        CONTINUE;
      ENDIF
      TPWrite "DEF";
    ENDFOR
    WHILE n < 5 DO
      n := n + 1;
      IF n = 2 CONTINUE;
    ENDWHILE
  ENDPROC
ENDMODULE

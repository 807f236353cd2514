MODULE continue_statement
! @section 4.9
! @expect ok
! @description The example of section 4.9.
  PROC main()
    FOR i FROM 1 TO 5 DO
      TPWrite "ABC"; ! will be run for i = 1, 2, 3, 4, 5
      IF ( i > 3) THEN
        CONTINUE;
      ENDIF
      TPWrite "DEF"; ! will only be run for i = 1, 2, 3
    ENDFOR
  ENDPROC
ENDMODULE

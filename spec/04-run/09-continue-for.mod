MODULE continue_for
! @format 3
! @section 4.9
! @expect ok
! @description Section 4.9's example: ABC is written for i = 1 to 5, DEF only for i = 1, 2, 3, since CONTINUE skips the rest of the body and starts the next iteration.
! @output ABC
! @output DEF
! @output ABC
! @output DEF
! @output ABC
! @output DEF
! @output ABC
! @output ABC
! @exit 0
  PROC main()
    FOR i FROM 1 TO 5 DO
      TPWrite "ABC";
      IF (i > 3) THEN
        CONTINUE;
      ENDIF
      TPWrite "DEF";
    ENDFOR
  ENDPROC
ENDMODULE

MODULE goto_out_of_compound
! @format 2
! @section 4.7
! @expect ok
! @description GOTO from inside IF, WHILE, FOR and TEST to a label of an enclosing statement list.
  VAR num i;
  PROC main()
    WHILE TRUE DO
      IF i > 10 THEN
        GOTO finish;
      ENDIF
      FOR k FROM 1 TO 3 DO
        TEST k
        CASE 2:
          GOTO finish;
        ENDTEST
      ENDFOR
      i := i + 1;
    ENDWHILE
    finish:
  ENDPROC
ENDMODULE

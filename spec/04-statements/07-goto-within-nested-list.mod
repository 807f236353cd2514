MODULE goto_within_nested_list
! @format 2
! @section 4.7
! @expect ok
! @description A label and a GOTO in the same nested statement list, and a GOTO from a deeper list to it.
  VAR num i;
  PROC main()
    IF i = 0 THEN
      again:
      i := i + 1;
      WHILE i < 5 DO
        IF i = 3 GOTO again;
        i := i + 1;
      ENDWHILE
      IF i < 10 GOTO again;
    ENDIF
  ENDPROC
ENDMODULE

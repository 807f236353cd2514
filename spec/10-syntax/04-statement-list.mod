MODULE statement_list
! @section 4.3
! @section 4.2
! @expect ok
! @description The examples of sections 4.2 and 4.3, and an empty statement list.
  VAR num a;
  VAR num b;
  VAR num index;
  VAR pos pos1;
  VAR pos pos2;
  VAR pos home;
  PROC main()
    IF a > b THEN
      pos1 := a * pos2;
      ! this is a comment
      pos2 := home;
    ENDIF
    WHILE index < 100 DO
      ! Loop start
      next:
      index := index + 1;
    ENDWHILE
    IF a > b THEN
    ENDIF
  ENDPROC
ENDMODULE

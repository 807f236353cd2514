MODULE comment_in_every_list ! a comment on the MODULE line is a type definition
! @section 2.10
! @expect ok
! @description A comment may be an element of each list of the grammar: type definitions, record components, data declarations, routines, statements.
  ! type definition list
  RECORD r
    num a; ! record component list
    num b;
  ENDRECORD
  ! data declaration list
  VAR num x;
  ! routine declaration list
  PROC main()
    ! data declaration list of the routine
    VAR num y;
    ! statement list
    IF x > 0 THEN ! statement list of THEN
      y := 1;
    ELSEIF x < 0 THEN ! statement list of ELSEIF
      y := 2;
    ELSE ! statement list of ELSE
      y := 3;
    ENDIF
    FOR i FROM 1 TO 2 DO ! statement list of FOR
    ENDFOR
    WHILE FALSE DO ! statement list of WHILE
    ENDWHILE
    TEST x
    CASE 1: ! statement list of CASE
    DEFAULT: ! statement list of DEFAULT
    ENDTEST
  BACKWARD ! backward handler
  ERROR ! error handler
  UNDO ! undo handler
  ENDPROC ! after a routine
ENDMODULE

MODULE break_in_error_handler
! @format 2
! @section 4.8
! @expect semantic-error 12:5
! @description The error handler is not inside the loop of the routine body: BREAK there is refused at BREAK.
  VAR num reg1;
  PROC main()
    WHILE reg1 < 10 DO
      reg1 := reg1 + 1;
    ENDWHILE
  ERROR
    BREAK;
  ENDPROC
ENDMODULE

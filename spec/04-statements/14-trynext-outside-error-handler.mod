MODULE trynext_outside_error_handler
! @format 2
! @section 4.14
! @expect semantic-error 9:7
! @description TRYNEXT belongs in an error handler; in a loop of the body it is refused at TRYNEXT.
  VAR num n;
  PROC main()
    WHILE n < 3 DO
      TRYNEXT;
    ENDWHILE
  ENDPROC
ENDMODULE

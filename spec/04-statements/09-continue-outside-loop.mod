MODULE continue_outside_loop
! @format 2
! @section 4.9
! @expect semantic-error 9:7
! @description CONTINUE can only be used in a WHILE or FOR loop; refused at CONTINUE.
  VAR num n;
  PROC main()
    IF n > 3 THEN
      CONTINUE;
    ENDIF
  ENDPROC
ENDMODULE

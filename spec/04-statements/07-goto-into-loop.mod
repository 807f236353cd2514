MODULE goto_into_loop
! @format 2
! @section 4.7
! @expect semantic-error 12:20
! @description A GOTO may not jump into the statement list of a loop; refused at the label name after GOTO.
  VAR num i;
  PROC main()
    WHILE i < 10 DO
      body:
      i := i + 1;
    ENDWHILE
    IF i > 20 GOTO body;
  ENDPROC
ENDMODULE

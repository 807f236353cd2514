MODULE break_outside_loop
! @format 2
! @section 4.8
! @expect semantic-error 9:5
! @description BREAK can only be used in a WHILE or FOR loop; refused at BREAK.
  VAR num reg1;
  PROC main()
    reg1 := 1;
    BREAK;
  ENDPROC
ENDMODULE

MODULE assignment_equals
! @section 4.5
! @expect syntax-error 7:7
! @description Assignment is written ':=': x = 1 is a procedure call x whose argument cannot begin with '='.
  VAR num x;
  PROC main()
    x = 1;
  ENDPROC
ENDMODULE

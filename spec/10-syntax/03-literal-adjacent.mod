MODULE literal_adjacent
! @section 3.5
! @expect syntax-error 7:12
! @description Two literals need an operator between them.
  VAR num x;
  PROC main()
    x := 1 2;
  ENDPROC
ENDMODULE

MODULE endwhile_missing
! @section 4.19
! @expect syntax-error 9:3
! @description A WHILE left open is refused at the ENDPROC that comes while it is open. The hint names the line of the WHILE.
  VAR num a;
  PROC main()
    WHILE a > 1 DO
      a := a - 1;
  ENDPROC
ENDMODULE

MODULE endproc_missing
! @section 5.4
! @expect syntax-error 9:3
! @description A procedure left open is refused at the next PROC. The hint names the open procedure and its line.
  VAR num a;
  PROC main()
    a := 1;

  PROC other()
    a := 2;
  ENDPROC
ENDMODULE

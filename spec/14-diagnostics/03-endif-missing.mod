MODULE endif_missing
! @section 4.16
! @expect syntax-error 10:3
! @description An IF left open is refused at the ENDPROC that comes while it is open. The hint names the line of the IF.
  VAR num a;
  PROC main()
    IF a > 1 THEN
      a := 2;
    a := 3;
  ENDPROC
ENDMODULE

MODULE else_if
! @section 4.16
! @expect syntax-error 13:3
! @description ELSE IF opens a nested IF, which the first ENDIF closes; the outer IF is then open at ENDPROC. The hint says to write ELSEIF.
  VAR num a;
  PROC main()
    IF a > 1 THEN
      a := 2;
    ELSE IF a < 0 THEN
      a := 0;
    ENDIF
    a := 3;
  ENDPROC
ENDMODULE

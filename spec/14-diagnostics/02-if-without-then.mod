MODULE if_without_then
! @section 4.16
! @section 4.17
! @expect syntax-error 10:5
! @description An IF without THEN is a compact IF (4.17) whose statement is the next one; the error is at the ENDIF that then closes nothing. The hint names the IF and its condition.
  VAR num a;
  PROC main()
    IF a > 1
      a := 2;
    ENDIF
  ENDPROC
ENDMODULE

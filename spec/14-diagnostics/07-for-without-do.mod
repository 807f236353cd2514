MODULE for_without_do
! @section 4.18
! @expect syntax-error 7:23
! @description FOR without DO: the error is at the first statement of the body, where DO (or STEP) was due.
  VAR num a;
  PROC main()
    FOR i FROM 1 TO 3 a := i;
    ENDFOR
  ENDPROC
ENDMODULE

MODULE for_fractional_step
! @format 3
! @section 4.18
! @expect ok
! @description The loop variable is a num and the step need not be an integer: FROM 0 TO 1 STEP 0.25 runs 5 times (0, 0.25, 0.5, 0.75, 1, all exact in binary).
! @output 0
! @output 1
! @output 2
! @output 3
! @output 4
! @output iterations=5
! @exit 0
  PROC main()
    VAR num n;
    FOR x FROM 0 TO 1 STEP 0.25 DO
      TPWrite "" \Num:=x * 4;
      n := n + 1;
    ENDFOR
    TPWrite "iterations=" \Num:=n;
  ENDPROC
ENDMODULE

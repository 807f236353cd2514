MODULE for_step
! @format 3
! @section 4.18
! @expect ok
! @description An explicit STEP; the loop ends as soon as the updated variable is outside the range, even when the range end is not hit exactly.
! @output 1
! @output 5
! @output 9
! @output 10
! @output 7
! @output 4
! @output 1
! @exit 0
  PROC main()
    FOR i FROM 1 TO 10 STEP 4 DO
      TPWrite "" \Num:=i;
    ENDFOR
    FOR i FROM 10 TO 1 STEP -3 DO
      TPWrite "" \Num:=i;
    ENDFOR
  ENDPROC
ENDMODULE

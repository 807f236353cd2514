MODULE for_counts_down
! @format 3
! @section 4.18
! @expect ok
! @description Without STEP, a decreasing range has the default step -1 (section 4.18): FOR i FROM 3 TO 1 counts 3, 2, 1.
! @output 3
! @output 2
! @output 1
! @exit 0
  PROC main()
    FOR i FROM 3 TO 1 DO
      TPWrite "" \Num:=i;
    ENDFOR
  ENDPROC
ENDMODULE

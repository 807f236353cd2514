MODULE for_ascending
! @format 3
! @section 4.18
! @expect ok
! @description The loop variable starts with the FROM value and goes up by the default step 1 while it stays within the range (section 4.18).
! @output 1
! @output 2
! @output 3
! @exit 0
  PROC main()
    FOR i FROM 1 TO 3 DO
      TPWrite "" \Num:=i;
    ENDFOR
  ENDPROC
ENDMODULE

MODULE break_innermost_loop
! @format 3
! @section 4.8
! @expect ok
! @description BREAK ends the smallest enclosing loop only (section 4.8): the outer FOR goes on with its next iteration.
! @output 1 1
! @output 2 1
! @output 3 1
! @exit 0
  PROC main()
    FOR i FROM 1 TO 3 DO
      FOR j FROM 1 TO 3 DO
        IF j = 2 BREAK;
        TPWrite NumToStr(i, 0) + " " + NumToStr(j, 0);
      ENDFOR
    ENDFOR
  ENDPROC
ENDMODULE

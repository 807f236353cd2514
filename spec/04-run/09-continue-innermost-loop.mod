MODULE continue_innermost_loop
! @format 3
! @section 4.9
! @expect ok
! @description CONTINUE starts the next iteration of the smallest enclosing loop: the inner loop goes on with j = 2, the outer loop is unaffected.
! @output 1 2
! @output 2 2
! @exit 0
  PROC main()
    FOR i FROM 1 TO 2 DO
      FOR j FROM 1 TO 2 DO
        IF j = 1 CONTINUE;
        TPWrite NumToStr(i, 0) + " " + NumToStr(j, 0);
      ENDFOR
    ENDFOR
  ENDPROC
ENDMODULE

MODULE goto_out_of_loops
! @format 3
! @section 4.7
! @section 4.18
! @section 4.19
! @expect ok
! @description A GOTO from inside nested loops to a label of the routine's statement list leaves both loops at once.
! @output 1 1
! @output 1 2
! @output left at 1 2
! @exit 0
  PROC main()
    VAR num a;
    VAR num b;
    WHILE TRUE DO
      a := a + 1;
      FOR j FROM 1 TO 5 DO
        b := j;
        TPWrite NumToStr(a, 0) + " " + NumToStr(b, 0);
        IF j = 2 GOTO done;
      ENDFOR
    ENDWHILE
    done:
    TPWrite "left at " + NumToStr(a, 0) + " " + NumToStr(b, 0);
  ENDPROC
ENDMODULE

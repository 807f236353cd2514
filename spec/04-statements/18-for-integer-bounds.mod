MODULE for_integer_bounds
! @format 3
! @section 4.18
! @expect ok
! @description FOR with integer FROM, TO and STEP (counted on an int by the closure engine) and with bounds beyond 2^23 or a fractional step (counted on the num): the same rounds; CONTINUE and BREAK in the body; a negative step; a step of 0.5.
! @output  1 3 5 7
! @output  8388606 8388608 8388610
! @output  3 2 1 0
! @output  0.0 0.5 1.0
! @output sum 19
! @exit 0
  PROC main()
    VAR string line;
    VAR num sum := 0;
    line := "";
    FOR k FROM 1 TO 9 STEP 2 DO
      IF k = 9 BREAK;
      line := line + " " + NumToStr(k, 0);
    ENDFOR
    TPWrite line;
    line := "";
    FOR k FROM 8388606 TO 8388610 STEP 2 DO
      line := line + " " + NumToStr(k, 0);
    ENDFOR
    TPWrite line;
    line := "";
    FOR k FROM 3 TO 0 DO
      line := line + " " + NumToStr(k, 0);
    ENDFOR
    TPWrite line;
    line := "";
    FOR k FROM 0 TO 1 STEP 0.5 DO
      line := line + " " + NumToStr(k, 1);
    ENDFOR
    TPWrite line;
    FOR k FROM 1 TO 10 DO
      IF k MOD 3 = 0 CONTINUE;
      IF k > 7 BREAK;
      sum := sum + k;
    ENDFOR
    TPWrite "sum " \Num:=sum;
  ENDPROC
ENDMODULE

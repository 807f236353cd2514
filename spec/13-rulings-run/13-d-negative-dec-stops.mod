MODULE rulings_round_negative_dec
! @format 3
! @section 13
! @section 7.1
! @expect ok
! @description R-13-d: a negative \Dec is ERR_ARGVALERR; with no handler the task stops at the statement that calls Round.
! @output 3.8
! @exit 1
! @error ERR_ARGVALERR 16:5
  PROC main()
    VAR num dec := 1;
    VAR num x;
    TPWrite ValToStr(Round(3.75 \Dec:=dec));
    dec := dec - 2;
    x := 0;
    x := Round(3.75 \Dec:=dec);
    TPWrite "not reached";
  ENDPROC
ENDMODULE

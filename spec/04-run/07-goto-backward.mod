MODULE goto_backward
! @format 3
! @section 4.7
! @section 4.4
! @expect ok
! @description Section 4.7's example: GOTO next continues at the label next, which stands before it, so the statements between run again until the condition stops it.
! @output i=1
! @output i=2
! @output i=3
! @output done
! @exit 0
  PROC main()
    VAR num i;
    next:
    i := i + 1;
    TPWrite "i=" \Num:=i;
    IF i < 3 GOTO next;
    TPWrite "done";
  ENDPROC
ENDMODULE

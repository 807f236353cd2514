MODULE exit_in_test_default
! @format 3
! @section 4.12
! @section 4.20
! @expect ok
! @description Section 4.12's example: an illegal state reaches the DEFAULT of a TEST, which writes a message and ends the task with EXIT, from inside a loop.
! @output ready
! @output Fatal error: illegal state
! @exit 0
  CONST num ready := 1;
  VAR num state := 1;
  PROC main()
    WHILE TRUE DO
      TEST state
      CASE ready:
        TPWrite "ready";
        state := 9;
      DEFAULT:
        ! illegal/unknown state - abort
        TPWrite "Fatal error: illegal state";
        EXIT;
      ENDTEST
    ENDWHILE
  ENDPROC
ENDMODULE

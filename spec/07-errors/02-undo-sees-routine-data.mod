MODULE undo_sees_routine_data
! @format 3
! @section 1.2
! @section 7.2
! @expect ok
! @description The UNDO handler is part of the routine: it sees the routine's data with the values they had when the routine was abandoned (the example's "Close log" closes the routine's own file).
! @output undo sees stage=2
! @output main handler
! @exit 0
  PROC p()
    VAR num stage;
    stage := 1;
    stage := 2;
    RAISE 4;
    stage := 3;
  UNDO
    TPWrite "undo sees stage=" \Num:=stage;
  ENDPROC
  PROC main()
    p;
  ERROR
    TPWrite "main handler";
    TRYNEXT;
  ENDPROC
ENDMODULE

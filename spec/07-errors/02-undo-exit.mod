MODULE undo_exit
! @format 3
! @section 1.2
! @section 4.12
! @expect ok
! @description EXIT ends the task and so abandons every routine of the call chain: their UNDO handlers run, innermost first, the entry routine's last.
! @output in inner
! @output inner undo
! @output outer undo
! @output main undo
! @exit 0
  PROC inner()
    TPWrite "in inner";
    EXIT;
  UNDO
    TPWrite "inner undo";
  ENDPROC
  PROC outer()
    inner;
  UNDO
    TPWrite "outer undo";
  ENDPROC
  PROC main()
    outer;
  UNDO
    TPWrite "main undo";
  ENDPROC
ENDMODULE

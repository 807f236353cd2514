MODULE undo_not_on_normal_end
! @format 3
! @section 1.2
! @section 5.4
! @expect ok
! @description A routine that ends normally, at ENDPROC or by RETURN, is not abandoned: its UNDO handler does not run (section 1.2: only an aborted routine runs it); neither does the entry routine's when the task ends normally.
! @output p end
! @output q return
! @output main end
! @exit 0
  PROC p()
    TPWrite "p end";
  UNDO
    TPWrite "wrong: p undo";
  ENDPROC
  PROC q()
    TPWrite "q return";
    RETURN;
  UNDO
    TPWrite "wrong: q undo";
  ENDPROC
  PROC main()
    p;
    q;
    TPWrite "main end";
  UNDO
    TPWrite "wrong: main undo";
  ENDPROC
ENDMODULE

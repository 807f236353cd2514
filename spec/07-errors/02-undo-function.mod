MODULE undo_function
! @format 3
! @section 1.2
! @section 5.5
! @expect ok
! @description A function may have an UNDO handler (section 5.5); it runs when the function is abandoned by an error raised inside it.
! @output f undo
! @output main handler
! @exit 0
  FUNC num f()
    RAISE 4;
  UNDO
    TPWrite "f undo";
  ENDFUNC
  PROC main()
    VAR num x;
    x := f();
  ERROR
    TPWrite "main handler";
    TRYNEXT;
  ENDPROC
ENDMODULE

MODULE exit_in_function
! @format 3
! @section 4.12
! @expect ok
! @description EXIT in a function called in the middle of an expression ends the task; the expression is never completed.
! @output in function
! @exit 0
  FUNC num f()
    TPWrite "in function";
    EXIT;
  ENDFUNC
  PROC main()
    VAR num x;
    x := 1 + f();
    TPWrite "wrong";
  ENDPROC
ENDMODULE

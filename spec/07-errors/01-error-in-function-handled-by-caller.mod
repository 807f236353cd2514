MODULE error_in_function_caller
! @format 3
! @section 7.1
! @section 3.11
! @expect ok
! @description An error in a function without error handler is raised again at the call, in the statement evaluating the expression; the caller's handler takes it and RETURN ends the caller.
! @output caller handler
! @output back in main
! @exit 0
  VAR num a{2} := [1, 2];
  FUNC num get(num i)
    RETURN a{i};
  ENDFUNC
  PROC use()
    VAR num x;
    x := 1 + get(5);
    TPWrite "wrong";
  ERROR
    IF ERRNO = ERR_OUTOFBND TPWrite "caller handler";
    RETURN;
  ENDPROC
  PROC main()
    use;
    TPWrite "back in main";
  ENDPROC
ENDMODULE

MODULE error_called_by_handler
! @format 3
! @section 7.1
! @expect ok
! @description An error in a function called from an error handler, the function having no handler of its own, comes back into the handler and goes to the system error handler; it is reported where it occurred, in the function.
! @output handler
! @exit 1
! @error ERR_OUTOFBND 11:5
  VAR num a{2};
  FUNC num get(num i)
    RETURN a{i};
  ENDFUNC
  PROC main()
    VAR num x;
    RAISE 5;
  ERROR
    TPWrite "handler";
    x := get(3);
    TPWrite "wrong";
  ENDPROC
ENDMODULE

MODULE run_unknown_names
  PROC main()
    VAR num n;
    n := missing_function(1);
  ERROR
    TPWrite "handled: " \Bool:=ERRNO = ERR_REFUNKFUN;
    TRYNEXT;
    ! After the handler: an unknown procedure, bound late.
  ENDPROC
  PROC second()
    % "no_such_procedure" %;
  ENDPROC
ENDMODULE

MODULE raise_system_error
  ! RAISE ERR_ARGVALERR in an error handler: ERR_ARGVALERR (1104) is no number RAISE raises
  ! (§4.11: 1 to 90, or one BookErrNo booked), and the message says what to write instead.
  PROC check_value(num x)
    VAR num y;
    y := 1 / x;
  ERROR
    RAISE ERR_ARGVALERR;
  ENDPROC
  PROC main()
    check_value 0;
  ENDPROC
ENDMODULE

MODULE conditional_duplicate_stops
! @format 3
! @section 3.11
! @section 12
! @expect ok
! @description Two conditional arguments of mutually exclusive alternatives both present (ERR_ARGDUPCND) stop the task at the call that passes them, when nothing handles the error.
! @output pick=1
! @exit 1
! @error ERR_ARGDUPCND 16:5
  FUNC num pick(\num speed | num time)
    IF Present(speed) RETURN speed;
    IF Present(time) RETURN time;
    RETURN 0;
  ENDFUNC
  PROC go(\num speed, \num time)
    TPWrite "pick=" \Num:=pick(\speed ? speed \time ? time);
  ENDPROC
  PROC main()
    go \speed:=1;
    go \speed:=1 \time:=2;
  ENDPROC
ENDMODULE

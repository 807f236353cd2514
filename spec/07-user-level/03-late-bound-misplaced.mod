MODULE late_bound_misplaced
! @format 3
! @section 7.3
! @section 4.6
! @expect ok
! @description A late-bound call of RaiseToUser outside the error handler of a NOSTEPIN routine, which the static check cannot see, stops the task with ERR_ILLRAISE at the call: there is no error of a NOSTEPIN routine to hand on (doc/rulings.md R-7.3-n).
! @output start
! @exit 1
! @error ERR_ILLRAISE 12:5
  PROC main()
    TPWrite "start";
    % "RaiseToUser" % \BreakOff;
    TPWrite "not reached";
  ERROR
    TPWrite "not this handler";
  ENDPROC
ENDMODULE

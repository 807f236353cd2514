MODULE late_binding_constant_unchanged
! @format 3
! @section 4.6
! @section 5.2
! @expect ok
! @description A constant passed by a late-bound call to a VAR parameter is refused when the call runs (ERR_ARGNOTVAR, chapter 12): the system error handler reports it at the call, and the procedure never runs.
! @exit 1
! @error ERR_ARGNOTVAR 15:5
  CONST num limit := 5;
  PROC reset(VAR num x)
    TPWrite "reset";
    x := 0;
  ENDPROC
  PROC main()
    % "reset" % limit;
    TPWrite "wrong";
  ENDPROC
ENDMODULE

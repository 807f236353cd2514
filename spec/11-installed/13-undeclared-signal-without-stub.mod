MODULE undeclared_signal_without_stub
! @format 3
! @section 13
! @options allow-unknown
! @expect ok
! @description With --allow-unknown alone, an undeclared name passed as a signal stays unknown: reaching it is the execution error ERR_REFUNKDAT (doc/rulings.md R-13-i, R-13-aa); only --stub-unmodelled as well makes it a virtual signal.
! @output before
! @exit 1
! @error ERR_REFUNKDAT 12:5
  PROC main()
    TPWrite "before";
    Set doClamp;
    TPWrite "after";
  ENDPROC
ENDMODULE

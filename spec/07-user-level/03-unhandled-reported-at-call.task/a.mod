MODULE user_unhandled_at_call
! @format 3
! @section 7.3
! @section 9.4
! @expect ok
! @description An error that leaves the routines of a NOSTEPIN module unhandled is reported at the user level: the system error handler names the call in user code, not the statement inside the NOSTEPIN module, whose code the user is not shown (section 9.4; doc/rulings.md R-7.3-o).
! @output start
! @exit 1
! @error ERR_DIVZERO a.mod:12:5
  PROC main()
    TPWrite "start";
    tool 0;
  ENDPROC
ENDMODULE

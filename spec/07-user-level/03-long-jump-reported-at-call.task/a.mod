MODULE user_long_jump_at_call
! @format 3
! @section 7.3
! @section 7.2
! @expect ok
! @description A long jump from a NOSTEPIN routine to an error recovery point in user code carries the error at the user level too: main's recovery point takes error 56, and when its handler reaches its end, the system error handler reports the call in user code that led into the NOSTEPIN module (work's call of tool), not the RAISE inside the NOSTEPIN module (doc/rulings.md R-7.3-o).
! @output recovery point
! @exit 1
! @error 56 a.mod:16:5
  PROC main()
    work;
  ERROR (56)
    TPWrite "recovery point";
  ENDPROC
  PROC work()
    tool;
  ENDPROC
ENDMODULE

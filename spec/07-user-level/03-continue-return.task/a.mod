MODULE user_continue_return
! @format 3
! @section 7.3
! @expect ok
! @description RaiseToUser \Continue, and the user level's handler ends with RETURN: the user routine returns, and the NOSTEPIN routines it could have gone on in are abandoned with it, without running their UNDO handlers (doc/rulings.md R-7.3-p).
! @output user handler 9
! @output main goes on
! @exit 0
  PROC main()
    user;
    TPWrite "main goes on";
  ENDPROC
  PROC user()
    tool;
    TPWrite "not reached";
  ERROR
    TPWrite "user handler " \Num:=ERRNO;
    RETURN;
  ENDPROC
ENDMODULE

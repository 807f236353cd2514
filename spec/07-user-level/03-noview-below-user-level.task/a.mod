MODULE user_noview
! @format 3
! @section 7.3
! @section 9.2
! @expect ok
! @description The routines of a NOVIEW module are below the user level as those of a NOSTEPIN module (a module whose code cannot be viewed cannot be stepped into, doc/rulings.md R-9.4-a): RaiseToUser is allowed in their error handlers and hands the error to main's handler.
! @output main handler 3
! @output done
! @exit 0
  PROC main()
    hidden;
    TPWrite "done";
  ERROR
    TPWrite "main handler " \Num:=ERRNO;
    TRYNEXT;
  ENDPROC
ENDMODULE

MODULE user_error_number_illegal
! @format 3
! @section 7.3
! @section 4.11
! @expect ok
! @description RaiseToUser \ErrorNumber with a number that is no error number (outside 1..90, not booked, not an ERR_ constant) is ERR_ILLRAISE, as for RAISE (section 4.11); raised in an error handler, it goes to the system error handler, and is reported at the user level (doc/rulings.md R-7.3-o).
! @output tool handler
! @exit 1
! @error ERR_ILLRAISE a.mod:11:5
  PROC main()
    tool;
  ERROR
    TPWrite "main handler";
    TRYNEXT;
  ENDPROC
ENDMODULE

MODULE raise_0_handled
! @format 3
! @section 4.11
! @section 12
! @expect ok
! @description RAISE 0 raises ERR_ILLRAISE, which the routine's handler can see in ERRNO like any execution error.
! @output illraise=TRUE
! @output after
! @exit 0
  VAR num zero;
  PROC main()
    RAISE zero;
    TPWrite "after";
  ERROR
    TPWrite "illraise=" \Bool:=ERRNO = ERR_ILLRAISE;
    TRYNEXT;
  ENDPROC
ENDMODULE

MODULE raise_91
! @format 3
! @section 4.11
! @section 12
! @expect ok
! @description An error number outside 1 to 90 in RAISE is itself an execution error, ERR_ILLRAISE (chapter 12; doc/rulings.md R-4.11), at the RAISE.
! @output before
! @exit 1
! @error ERR_ILLRAISE 12:5
  PROC main()
    TPWrite "before";
    RAISE 91;
    TPWrite "after";
  ENDPROC
ENDMODULE

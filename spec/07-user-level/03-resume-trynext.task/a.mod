MODULE user_resume_trynext
! @format 3
! @section 7.3
! @expect ok
! @description RaiseToUser \Resume (the manual's name of the switch, section 7.3) with \ErrorNumber: the user level's handler sees that number in ERRNO; its TRYNEXT goes on in the NOSTEPIN routine after the statement that caused the error.
! @output inner handler
! @output main handler 12
! @output inner goes on
! @output done
! @exit 0
  PROC main()
    tool;
    TPWrite "done";
  ERROR
    TPWrite "main handler " \Num:=ERRNO;
    TRYNEXT;
  ENDPROC
ENDMODULE

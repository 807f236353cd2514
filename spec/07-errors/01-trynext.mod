MODULE trynext_after_error
! @format 3
! @section 4.14
! @section 7.1
! @expect ok
! @description TRYNEXT resumes with the statement after the one that caused the error (section 4.14); the failed assignment leaves its target unchanged.
! @output handler
! @output next x=1
! @exit 0
  PROC main()
    VAR num x := 1;
    VAR num d;
    x := 5 / d;
    TPWrite "next x=" \Num:=x;
  ERROR
    TPWrite "handler";
    TRYNEXT;
  ENDPROC
ENDMODULE

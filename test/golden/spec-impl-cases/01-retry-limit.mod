MODULE retry_limit
! @format 3
! @section 4.13
! @section 7.5
! @expect ok
! @description The number of retries is limited by No Of Retry (section 7.5: more than 4 retries need the parameter changed), default 4: four RETRYs re-execute the statement, the fifth RETRY raises ERR_EXCRTYMAX, an error in the handler, so the system error handler stops the task at that RETRY.
! @output handler 1
! @output handler 2
! @output handler 3
! @output handler 4
! @output handler 5
! @exit 1
! @error ERR_EXCRTYMAX 22:5
  VAR num n;
  PROC main()
    VAR num d;
    VAR num x;
    x := 1 / d;
  ERROR
    n := n + 1;
    TPWrite "handler " \Num:=n;
    RETRY;
  ENDPROC
ENDMODULE

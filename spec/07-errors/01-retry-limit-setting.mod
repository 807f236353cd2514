MODULE retry_limit_setting
! @format 3
! @section 4.13
! @section 7.5
! @expect ok
! @description With No Of Retry set to 2 the third RETRY raises ERR_EXCRTYMAX.
! @retry-limit 2
! @output handler 1
! @output handler 2
! @output handler 3
! @exit 1
! @error ERR_EXCRTYMAX 19:5
  VAR num n;
  PROC main()
    RAISE 1;
  ERROR
    n := n + 1;
    TPWrite "handler " \Num:=n;
    RETRY;
  ENDPROC
ENDMODULE

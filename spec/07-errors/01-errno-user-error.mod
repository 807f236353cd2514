MODULE errno_user_error
! @format 3
! @section 7.1
! @section 4.11
! @expect ok
! @description RAISE with an error number raises that error (section 4.11); in the handler ERRNO is the number itself.
! @output errno=42
! @exit 0
  PROC main()
    RAISE 42;
    TPWrite "wrong";
  ERROR
    TPWrite "errno=" \Num:=ERRNO;
    RETURN;
  ENDPROC
ENDMODULE

MODULE initialiser_errno
! @format 2
! @section 2.22
! @section 3.2
! @section 12
! @expect semantic-error 9:21
! @description ERRNO is a (read-only) variable: it may not appear in a constant expression; refused at ERRNO.
  PROC main()
    VAR num code := ERRNO;
  ENDPROC
ENDMODULE

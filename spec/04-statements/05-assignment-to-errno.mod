MODULE assignment_to_errno
! @format 2
! @section 4.5
! @section 12
! @expect semantic-error 8:5
! @description ERRNO is read-only, updated only by the system (chapter 12); refused at the target.
  PROC main()
    ERRNO := 0;
  ENDPROC
ENDMODULE

MODULE label_is_no_op
! @format 3
! @section 4.4
! @expect ok
! @description A label is a no-op statement (section 4.4): execution passes through it to the next statement.
! @output one
! @output two
! @exit 0
  PROC main()
    TPWrite "one";
    next:
    TPWrite "two";
  ENDPROC
ENDMODULE

MODULE goto_forward
! @format 3
! @section 4.7
! @expect ok
! @description A GOTO to a later label skips the statements in between (section 4.7).
! @output one
! @output three
! @exit 0
  PROC main()
    TPWrite "one";
    GOTO skip;
    TPWrite "two";
    skip:
    TPWrite "three";
  ENDPROC
ENDMODULE

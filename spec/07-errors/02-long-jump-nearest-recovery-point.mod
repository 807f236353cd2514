MODULE long_jump_nearest
! @format 3
! @section 7.2
! @expect ok
! @description The search goes from the calling routine toward the top of the call chain: of two recovery points naming 56, the nearer one (in middle) takes the error.
! @output middle recovery point
! @output back in main
! @exit 0
  PROC main()
    middle;
    TPWrite "back in main";
  ERROR (56)
    TPWrite "wrong: main recovery point";
    RETURN;
  ENDPROC
  PROC middle()
    deep;
  ERROR (56)
    TPWrite "middle recovery point";
    RETURN;
  ENDPROC
  PROC deep()
    RAISE 56;
  ENDPROC
ENDMODULE

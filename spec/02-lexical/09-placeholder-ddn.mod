MODULE placeholder_ddn
! @section 2.9
! @section 2.18
! @expect ok
! @description <DDN> stands for a data declaration, at module level and in a routine.
  <DDN>
  PROC main()
    <DDN>
    x := 1;
  ENDPROC
ENDMODULE

MODULE placeholder_arg
! @section 2.9
! @section 4.6
! @expect ok
! @description <ARG> stands for a procedure call argument, first or after a comma.
  PROC main()
    p <ARG>;
    p 1, <ARG>, <ARG>;
  ENDPROC
ENDMODULE

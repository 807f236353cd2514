MODULE raise_number_out_of_range
! @format 2
! @section 4.11
! @section 12
! @expect ok
! @description Ruling: an error number outside 1..90 is an execution error (ERR_ILLRAISE, chapter 12), not a static one, even when constant.
  PROC main()
    RAISE 91;
  ENDPROC
ENDMODULE

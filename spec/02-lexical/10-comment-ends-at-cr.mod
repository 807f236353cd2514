MODULE comment_ends_at_cr
! @section 2.10
! @expect ok
! @description A comment ends at a newline, a lone carriage return included: the ENDPROC after it is read.
  VAR num x;
  PROC main()
    x := 1; ! this comment ends at a lone CRENDPROC
ENDMODULE

MODULE comment_between_arguments
! @section 2.10
! @expect syntax-error 6:10
! @description A comment is not white space: it cannot stand between the arguments of a call.
  PROC main()
    p 1, ! first
      2;
  ENDPROC
ENDMODULE

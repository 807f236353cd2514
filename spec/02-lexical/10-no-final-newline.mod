MODULE no_final_newline
! @section 2.10
! @expect ok
! @description A file that does not end with a line break is accepted by default (dialect extension).
  VAR num x;
  PROC main()
    x := 1;
  ENDPROC
ENDMODULE
MODULE tab_counts_one_column
! @section 2.10
! @section 2.2
! @expect syntax-error 8:10
! @description A tab is one character for column counting.
  VAR num x;
  PROC main()
		x := 1 2;
  ENDPROC
ENDMODULE

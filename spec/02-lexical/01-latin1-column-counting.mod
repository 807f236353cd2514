MODULE latin1_column_counting
! @section 2.1
! @section 2.7
! @expect syntax-error 8:16
! @description In an ISO 8859-1 file each byte is one character for column counting.
  VAR string s;
  PROC main()
    s := "ייי" 1;
  ENDPROC
ENDMODULE

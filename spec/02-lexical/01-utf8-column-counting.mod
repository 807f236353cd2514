MODULE utf8_column_counting
! @section 2.1
! @section 2.7
! @expect syntax-error 8:17
! @description Columns count characters, not bytes or UTF-16 units: the error follows a string holding two-byte and four-byte characters.
  VAR string s;
  PROC main()
    s := "éé😀é" 1;
  ENDPROC
ENDMODULE

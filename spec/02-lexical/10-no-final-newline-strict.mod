MODULE no_final_newline_strict
! @section 2.10
! @expect syntax-error 10:9
! @options strict
! @description In strict mode a file must end with a line break; the error is at the last character of the file (doc/dialect.md).
  VAR num x;
  PROC main()
    x := 1;
  ENDPROC
ENDMODULE
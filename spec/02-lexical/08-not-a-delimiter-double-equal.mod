MODULE not_a_delimiter_double_equal
! @section 2.8
! @expect syntax-error 8:11
! @description "==" is not a delimiter: it is two "=".
  VAR num a;
  VAR num b;
  PROC main()
    IF a == b THEN
      a := b;
    ENDIF
  ENDPROC
ENDMODULE

MODULE not_a_delimiter_less_equal_rever
! @section 2.8
! @expect syntax-error 8:11
! @description "=<" is not a compound delimiter: it is "=" followed by "<".
  VAR num a;
  VAR num b;
  PROC main()
    IF a =< b THEN
      a := b;
    ENDIF
  ENDPROC
ENDMODULE

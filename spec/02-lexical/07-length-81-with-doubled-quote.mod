MODULE length_81_with_doubled_quote
! @section 2.7
! @section 2.13
! @expect lexical-error 8:10
! @description A doubled quote is one byte of the value: 80 characters and "" make 81 bytes.
  VAR string s;
  PROC main()
    s := "aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa""";
  ENDPROC
ENDMODULE

MODULE length_80_with_doubled_quote
! @section 2.7
! @section 2.13
! @expect ok
! @description A doubled quote is one byte of the value: 79 characters and "" make 80 bytes.
  VAR string s;
  PROC main()
    s := "aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa""";
  ENDPROC
ENDMODULE

MODULE manual_examples
! @section 2.7
! @expect ok
! @description The examples of string literals printed in section 2.7.
  VAR string s;
  PROC main()
    s := "A string literal";
    s := "Contains a "" character";
    s := "Ends with BEL control character \07";
    s := "Contains a \\ character";
  ENDPROC
ENDMODULE

MODULE character_codes
! @section 2.7
! @expect ok
! @description <character code> ::= '\' <hex digit> <hex digit>, either letter case.
  VAR string s;
  PROC main()
    s := "\00\0a\0A\7F\80\ff\FF";
    s := "\41\42\43";
  ENDPROC
ENDMODULE

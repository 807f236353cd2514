MODULE length_81_bytes
! @section 2.7
! @section 2.13
! @expect lexical-error 8:10
! @description A string literal whose value is 81 bytes exceeds the maximum of 80.
  VAR string s;
  PROC main()
    s := "aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa";
  ENDPROC
ENDMODULE

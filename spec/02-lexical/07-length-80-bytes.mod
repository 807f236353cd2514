MODULE length_80_bytes
! @section 2.7
! @section 2.13
! @expect ok
! @description A string literal whose value is exactly 80 bytes is accepted.
  VAR string s;
  PROC main()
    s := "aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa";
  ENDPROC
ENDMODULE

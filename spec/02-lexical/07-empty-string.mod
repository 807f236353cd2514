MODULE empty_string
! @section 2.7
! @expect ok
! @description A string literal holds zero or more characters.
  VAR string s;
  PROC main()
    s := "";
  ENDPROC
ENDMODULE

MODULE alias_equal_to_base
! @format 2
! @section 2.15
! @section 2.17
! @expect ok
! @description An alias name is replaced by its base type before types are compared: level and num, and two aliases of num, are equal types.
  ALIAS num level;
  ALIAS num depth;
  VAR level l;
  VAR depth d;
  VAR num n;
  PROC main()
    l := n;
    n := l;
    l := d;
  ENDPROC
ENDMODULE

MODULE mod_non_integer
! @format 3
! @section 3.12
! @section 12
! @expect ok
! @description The operands of MOD must represent integers (section 3.12, note i): 7 MOD 2.5 with the 2.5 in a variable raises ERR_NOTINTVAL.
! @exit 1
! @error ERR_NOTINTVAL 12:5
  PROC main()
    VAR num b := 2.5;
    VAR num x;
    x := 7 MOD b;
  ENDPROC
ENDMODULE

MODULE div_non_integer
! @format 3
! @section 3.12
! @section 12
! @expect ok
! @description The operands of DIV must represent integers (section 3.12, note i): 7.5 DIV 2 with the 7.5 in a variable raises ERR_NOTINTVAL (chapter 12) when it runs.
! @exit 1
! @error ERR_NOTINTVAL 12:5
  PROC main()
    VAR num a := 7.5;
    VAR num x;
    x := a DIV 2;
  ENDPROC
ENDMODULE

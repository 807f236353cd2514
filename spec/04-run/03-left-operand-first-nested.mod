MODULE left_operand_first_nested
! @format 3
! @section 3.1
! @expect ok
! @description In a - b * c the left operand a is evaluated before the right operand b * c, whose own left operand b comes before c (section 3.1); the same holds for a comparison and for string concatenation.
! @output a
! @output b
! @output c
! @output r=-5
! @output a
! @output b
! @output less
! @output a
! @output c
! @output ac
! @exit 0
  FUNC num val(string name, num v)
    TPWrite name;
    RETURN v;
  ENDFUNC
  FUNC string txt(string name)
    TPWrite name;
    RETURN name;
  ENDFUNC
  PROC main()
    VAR num r;
    VAR string s;
    r := val("a", 1) - val("b", 2) * val("c", 3);
    TPWrite "r=" \Num:=r;
    IF val("a", 1) < val("b", 2) THEN
      TPWrite "less";
    ENDIF
    s := txt("a") + txt("c");
    TPWrite s;
  ENDPROC
ENDMODULE

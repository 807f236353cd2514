MODULE initial_value_later_constant
! @format 3
! @section 3.2
! @section 2.20
! @section 2.24
! @expect ok
! @description Module data is in scope in its whole module (§2.20), so an initial value may name a constant declared further down; the values are known before the program runs (§3.2) and do not depend on the order of the declarations.
! @output x=42
! @output twice=42
! @output sum=63
! @exit 0
  VAR num x := twice;
  CONST num twice := 2 * once;
  CONST num once := 21;
  PROC main()
    CONST num sum := twice + once;
    VAR num y := sum;
    TPWrite "x=" \Num:=x;
    TPWrite "twice=" \Num:=twice;
    TPWrite "sum=" \Num:=y;
  ENDPROC
ENDMODULE

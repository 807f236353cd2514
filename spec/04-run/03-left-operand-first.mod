MODULE left_operand_first
! @format 3
! @section 3.1
! @expect ok
! @description The left operand of a binary operator is evaluated before the right one (section 3.1): each function writes its name when it is called.
! @output left
! @output right
! @output sum=3
! @exit 0
  FUNC num left()
    TPWrite "left";
    RETURN 1;
  ENDFUNC
  FUNC num right()
    TPWrite "right";
    RETURN 2;
  ENDFUNC
  PROC main()
    VAR num s;
    s := left() + right();
    TPWrite "sum=" \Num:=s;
  ENDPROC
ENDMODULE

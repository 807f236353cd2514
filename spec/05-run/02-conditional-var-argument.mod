MODULE conditional_var_argument
! @format 3
! @section 3.11
! @section 5.2
! @expect ok
! @description A present optional var parameter passed on with ? keeps the alias: the innermost update reaches the outermost argument.
! @output v=9
! @exit 0
  PROC inner(\VAR num target)
    IF Present(target) target := 9;
  ENDPROC
  PROC outer(\VAR num t)
    inner \target ? t;
  ENDPROC
  PROC main()
    VAR num v := 1;
    outer \t:=v;
    TPWrite "v=" \Num:=v;
  ENDPROC
ENDMODULE

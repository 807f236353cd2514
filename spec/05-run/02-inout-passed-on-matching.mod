MODULE inout_passed_on_matching
! @format 3
! @section 5.2
! @expect ok
! @description The accepted cells next to the two execution errors: an inout parameter bound to a variable passed on to a var parameter, and one bound to a persistent passed on to a pers parameter; the aliases chain, so the innermost update reaches the original argument.
! @output v=2
! @output p=3
! @exit 0
  VAR num v := 1;
  PERS num p := 1;
  PROC set_var(VAR num y)
    y := 2;
  ENDPROC
  PROC set_pers(PERS num y)
    y := 3;
  ENDPROC
  PROC mid_var(INOUT num x)
    set_var x;
  ENDPROC
  PROC mid_pers(INOUT num x)
    set_pers x;
  ENDPROC
  PROC main()
    mid_var v;
    mid_pers p;
    TPWrite "v=" \Num:=v;
    TPWrite "p=" \Num:=p;
  ENDPROC
ENDMODULE

MODULE routine_before_its_declaration
! @format 2
! @section 13
! @expect ok
! @description Routines and module data are visible in the whole module, before and after their declarations.
  VAR num n := 1;
  PROC main()
    helper;
    n := twice(n);
  ENDPROC
  PROC helper()
    n := n + 1;
  ENDPROC
  FUNC num twice(num x)
    RETURN 2 * x;
  ENDFUNC
ENDMODULE

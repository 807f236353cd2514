MODULE constant_declared_after_use
! @format 2
! @section 3.2
! @section 2.24
! @section 2.20
! @expect ok
! @description Module data is in scope in its whole module (§2.20): an initial value may name a constant declared further down. That is no cycle.
  VAR num x := twice;
  CONST num twice := 2 * once;
  CONST num once := 21;
  PROC main()
  ENDPROC
ENDMODULE

MODULE module_declaration_routine_befor
! @section 9.2
! @expect syntax-error 7:3
! @description Type definitions come first in a module.
  PROC main()
  ENDPROC
  ALIAS num n;
ENDMODULE

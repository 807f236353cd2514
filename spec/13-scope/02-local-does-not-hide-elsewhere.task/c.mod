MODULE report
! @format 2
! @section 2.20
! @section 2.17
! @expect semantic-error c.mod:8:14
! @description A LOCAL object of module b does not hide the global level of module a in module c, where level is a string; assigning 3 is refused.
  PROC set_level()
    level := 3;
  ENDPROC
ENDMODULE

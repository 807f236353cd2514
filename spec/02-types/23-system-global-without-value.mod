MODULE system_global_without_value
! @format 2
! @section 2.23
! @section 14
! @expect ok
! @description Only system-global persistents may omit the initial value (chapter 14's PERS num state).
  PERS num state;
  PERS pos home;
  PERS num table{3};
ENDMODULE

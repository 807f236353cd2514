MODULE declaration_function_value
! @format 2
! @section 2.16
! @section 5.5
! @expect ok
! @description Table of section 2.16, row function return value, column value: legal (atomic, record and alias types).
  ALIAS num level;
  FUNC pos origin()
    RETURN [0, 0, 0];
  ENDFUNC
  FUNC level low()
    RETURN 2.5;
  ENDFUNC
  FUNC bool yes()
    RETURN TRUE;
  ENDFUNC
ENDMODULE

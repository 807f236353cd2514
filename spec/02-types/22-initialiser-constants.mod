MODULE initialiser_constants
! @format 2
! @section 2.22
! @section 3.2
! @expect ok
! @description Constants, predefined constants and operations on them form constant expressions, at module level and in routines.
  CONST num radius := 25;
  CONST num pi := 3.141592654;
  VAR num area := pi * radius * radius;
  VAR errnum last := ERR_DIVZERO;
  PROC main()
    VAR num circumference := 2 * pi * radius;
    VAR pos centre := [radius, -radius, 0];
  ENDPROC
ENDMODULE

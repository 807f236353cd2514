MODULE alias_definitions
! @format 2
! @section 2.15
! @expect ok
! @description Aliases of atomic and record types, and the example of section 2.15: CONST level low := 2.5.
  ALIAS num level;
  ALIAS pos point;
  ALIAS bool flag;
  ALIAS string text;
  CONST level low := 2.5;
  CONST level high := 4.0;
  VAR point pt := [1, 2, 3];
  VAR flag ready := TRUE;
  VAR text greeting := "hello";
ENDMODULE

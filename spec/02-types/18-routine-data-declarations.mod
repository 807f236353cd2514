MODULE routine_data_declarations
! @format 2
! @section 2.18
! @expect ok
! @description Variables and constants declared in routines, with initialisers, arrays and placeholders.
  PROC main()
    VAR num n := 1;
    CONST num limit := 10;
    VAR pos p := [0, 0, limit];
    VAR num table{limit};
    <DDN>
    n := limit;
  ENDPROC
ENDMODULE

MODULE nested_loops_same_variable
! @format 2
! @section 4.18
! @expect ok
! @description An inner loop variable hides an outer one of the same name.
  VAR num total;
  PROC main()
    FOR i FROM 1 TO 3 DO
      FOR i FROM 1 TO 2 DO
        total := total + i;
      ENDFOR
      total := total + i;
    ENDFOR
  ENDPROC
ENDMODULE

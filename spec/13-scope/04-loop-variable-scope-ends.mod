MODULE loop_variable_scope_ends
! @format 2
! @section 4.18
! @section 2.20
! @expect semantic-error 12:14
! @description A loop variable's scope is its DO .. ENDFOR statement list: after ENDFOR the name is unknown.
  VAR num total;
  PROC main()
    FOR i FROM 1 TO 3 DO
      total := total + i;
    ENDFOR
    total := i;
  ENDPROC
ENDMODULE

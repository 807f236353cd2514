MODULE access_loop_variable_to_var
! @format 2
! @section 5.2
! @expect semantic-error 8:16
! @description Table of section 5.2, row read-only variable (FOR loop variable), column var: illegal; refused at the argument.
  PROC main()
    FOR i FROM 1 TO 3 DO
      take_var i;
    ENDFOR
  ENDPROC

  PROC take_in(num x)
  ENDPROC
  PROC take_var(VAR num x)
  ENDPROC
  PROC take_pers(PERS num x)
  ENDPROC
  PROC take_inout(INOUT num x)
  ENDPROC
ENDMODULE

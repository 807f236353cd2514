MODULE loop_variable_hides
! @format 2
! @section 4.18
! @expect ok
! @description A loop variable is declared by its appearance as a num and hides other objects of the same name.
  VAR string i := "text";
  VAR num total;
  PROC main()
    VAR bool k;
    FOR i FROM 1 TO 3 DO
      total := total + i;
    ENDFOR
    FOR k FROM 1 TO 2 DO
      total := total * k;
    ENDFOR
    i := "again";
  ENDPROC
ENDMODULE

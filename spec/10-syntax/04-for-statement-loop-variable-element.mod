MODULE for_statement_loop_variable_elem
! @section 4.18
! @expect syntax-error 7:10
! @description <loop variable> ::= <identifier>: an array element is not one.
  VAR num a{1};
  PROC main()
    FOR a{1} FROM 1 TO 10 DO
    ENDFOR
  ENDPROC
ENDMODULE

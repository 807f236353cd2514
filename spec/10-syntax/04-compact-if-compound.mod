MODULE compact_if_compound
! @section 4.17
! @expect syntax-error 7:10
! @description A compact IF holds a simple statement: WHILE is a compound statement.
  VAR bool b;
  PROC main()
    IF b WHILE b DO
    ENDWHILE
  ENDPROC
ENDMODULE

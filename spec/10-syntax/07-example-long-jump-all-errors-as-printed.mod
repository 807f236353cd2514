MODULE Example3
! @section 7.2
! @expect syntax-error 6:1
! @description The module Example3 of section 7.2 as printed: PROC main lacks the parentheses that <procedure declaration> requires.
PROC main
WHILE myFunction() = TRUE DO
    myRoutine;
ENDWHILE
EXIT;
ERROR (LONG_JMP_ALL_ERR)
TRYNEXT;
ENDPROC
ENDMODULE

MODULE Example3
! @section 7.2
! @expect ok
! @description The module Example3 of section 7.2 with the parentheses of PROC main() supplied.
PROC main()
WHILE myFunction() = TRUE DO
    myRoutine;
ENDWHILE
EXIT;
ERROR (LONG_JMP_ALL_ERR)
TRYNEXT;
ENDPROC
ENDMODULE

MODULE long_jump_example3
! @format 3
! @section 7.2
! @section 4.14
! @expect ok
! @description Section 7.2's Example3: an error in myFunction, called in the WHILE condition, is caught by main's ERROR (LONG_JMP_ALL_ERR); the WHILE is the statement in error, so TRYNEXT continues with the next statement, EXIT.
! @output myRoutine
! @output myRoutine
! @output recovery point
! @output before exit
! @exit 0
  VAR num calls;
  FUNC bool myFunction()
    calls := calls + 1;
    IF calls = 3 RAISE 30;
    RETURN TRUE;
  ENDFUNC
  PROC myRoutine()
    TPWrite "myRoutine";
  ENDPROC
  PROC main()
    WHILE myFunction() = TRUE DO
      myRoutine;
    ENDWHILE
    TPWrite "before exit";
    EXIT;
  ERROR (LONG_JMP_ALL_ERR)
    TPWrite "recovery point";
    TRYNEXT;
  ENDPROC
ENDMODULE

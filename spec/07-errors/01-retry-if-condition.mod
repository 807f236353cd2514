MODULE retry_if_condition
! @format 3
! @section 4.13
! @section 7.2
! @expect ok
! @description An error inside a function called in an IF condition: the statement that caused it is the IF itself (section 7.2), so RETRY evaluates the condition again.
! @output check 1
! @output handler
! @output check 2
! @output then
! @exit 0
  VAR num calls;
  FUNC bool check()
    calls := calls + 1;
    TPWrite "check " \Num:=calls;
    IF calls = 1 RAISE 3;
    RETURN TRUE;
  ENDFUNC
  PROC main()
    IF check() THEN
      TPWrite "then";
    ENDIF
  ERROR
    TPWrite "handler";
    RETRY;
  ENDPROC
ENDMODULE

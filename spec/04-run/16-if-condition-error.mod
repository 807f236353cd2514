MODULE if_condition_error
! @format 3
! @section 4.16
! @section 7.1
! @expect ok
! @description An error while evaluating the condition of an IF is an error of the IF statement: the system error handler reports it at the IF, and no branch runs.
! @exit 1
! @error ERR_DIVZERO 11:5
  VAR num d;
  PROC main()
    IF 1 / d > 0 THEN
      TPWrite "then";
    ELSE
      TPWrite "else";
    ENDIF
  ENDPROC
ENDMODULE

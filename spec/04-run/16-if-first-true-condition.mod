MODULE if_first_true_condition
! @format 3
! @section 4.16
! @expect ok
! @description The conditions of an IF are evaluated one after the other until one is true (section 4.16): only the first true branch runs, and the conditions after it are not evaluated.
! @output cond 1
! @output cond 2
! @output branch 2
! @exit 0
  FUNC bool cond(num n, bool v)
    TPWrite "cond " \Num:=n;
    RETURN v;
  ENDFUNC
  PROC main()
    IF cond(1, FALSE) THEN
      TPWrite "branch 1";
    ELSEIF cond(2, TRUE) THEN
      TPWrite "branch 2";
    ELSEIF cond(3, TRUE) THEN
      TPWrite "branch 3";
    ELSE
      TPWrite "else";
    ENDIF
  ENDPROC
ENDMODULE

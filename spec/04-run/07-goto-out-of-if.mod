MODULE goto_out_of_if
! @format 3
! @section 4.7
! @expect ok
! @description A GOTO inside an IF branch may reach a label of the enclosing statement list (doc/rulings.md R-4.7); the rest of the branch and of the IF is skipped.
! @output in branch
! @output at label
! @exit 0
  VAR bool yes := TRUE;
  PROC main()
    IF yes THEN
      TPWrite "in branch";
      GOTO out;
      TPWrite "wrong 1";
    ENDIF
    TPWrite "wrong 2";
    out:
    TPWrite "at label";
  ENDPROC
ENDMODULE

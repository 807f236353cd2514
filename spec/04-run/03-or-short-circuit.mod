MODULE or_short_circuit
! @format 3
! @section 3.1
! @expect ok
! @description OR does not evaluate its right operand when the left one is TRUE (section 3.1); when the left one is FALSE it does.
! @output first done
! @output side
! @output second false
! @exit 0
  VAR bool no := FALSE;
  VAR bool yes := TRUE;
  FUNC bool side()
    TPWrite "side";
    RETURN FALSE;
  ENDFUNC
  PROC main()
    IF yes OR side() THEN
      TPWrite "first done";
    ENDIF
    IF no OR side() THEN
      TPWrite "wrong";
    ELSE
      TPWrite "second false";
    ENDIF
  ENDPROC
ENDMODULE

MODULE and_short_circuit
! @format 3
! @section 3.1
! @expect ok
! @description AND does not evaluate its right operand when the left one is FALSE (section 3.1: the result is known after the left operand); when the left one is TRUE it does.
! @output first done
! @output side
! @output second done
! @exit 0
  VAR bool no := FALSE;
  VAR bool yes := TRUE;
  FUNC bool side()
    TPWrite "side";
    RETURN TRUE;
  ENDFUNC
  PROC main()
    IF no AND side() THEN
      TPWrite "wrong";
    ENDIF
    TPWrite "first done";
    IF yes AND side() THEN
      TPWrite "second done";
    ENDIF
  ENDPROC
ENDMODULE

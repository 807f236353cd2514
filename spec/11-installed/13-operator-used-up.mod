MODULE operator_used_up
! @format 3
! @section 13
! @expect ok
! @operator 13-operator-mismatch.operator
! @description When the operator's script has no answer left for a dialogue, or its next answer is for another routine, the run ends at the call with exit status 4 (doc/rulings.md R-13-ui2); under --operator UIMsgBox is not asked of the script before its turn.
! @output Go on?
! @output Again?
! @exit 4
! @error UIMsgBox 15:5
  PROC main()
    VAR num key;
    TPReadFK key, "Go on?", "Yes", "No", stEmpty, stEmpty, stEmpty;
    TPReadFK key, "Again?", "Yes", "No", "Skip", stEmpty, stEmpty;
    UIMsgBox "Start?";
    TPWrite "not reached";
  ENDPROC
ENDMODULE

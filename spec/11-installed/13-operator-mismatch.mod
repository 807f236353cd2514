MODULE operator_mismatch
! @format 3
! @section 13
! @expect ok
! @operator 13-operator-mismatch.operator
! @description An answer of the operator's script that the dialogue cannot take (TPReadFK's third key has no text) ends the run at the call with exit status 4, as a routine not modelled, naming the script's line (doc/rulings.md R-13-ui2). What ran before it ran.
! @output Go on?
! @output key 1
! @output Again?
! @exit 4
! @error TPReadFK 16:5
  PROC main()
    VAR num key;
    TPReadFK key, "Go on?", "Yes", "No", stEmpty, stEmpty, stEmpty;
    TPWrite "key " \Num:=key;
    TPReadFK key, "Again?", "Yes", "No", stEmpty, stEmpty, stEmpty;
    TPWrite "not reached";
  ENDPROC
ENDMODULE

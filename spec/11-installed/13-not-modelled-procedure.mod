MODULE not_modelled_procedure
! @format 3
! @section 13
! @expect ok
! @description A call of an installed procedure whose behaviour rapid-sem does not model yet (TPReadFK, the pendant's function keys) ends the run with exit status 4, reported at the call: the routine and the first character of the call statement. What ran before it ran.
! @output before
! @exit 4
! @error TPReadFK 12:5
  VAR num answer;
  PROC main()
    TPWrite "before";
    TPReadFK answer, "Go on?", "Yes", "No", "", "", "";
    TPWrite "after";
  ENDPROC
ENDMODULE

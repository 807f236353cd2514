MODULE not_modelled_function
! @format 3
! @section 13
! @expect ok
! @description A call of an installed function rapid-sem does not model yet (RunMode) inside an expression ends the run with exit status 4, reported at the function call itself (its name), not at the statement.
! @output 1
! @exit 4
! @error RunMode 13:22
  ! The running mode, which rapid-sem does not model.
  VAR num state := 1;
  PROC main()
    TPWrite "" \Num:=state;
    state := state + RunMode();
    TPWrite "" \Num:=state;
  ENDPROC
ENDMODULE

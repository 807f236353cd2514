MODULE trap_in_expression
! @format 2
! @section 3.11
! @section 5.1
! @expect semantic-error 9:10
! @description A trap routine is never called from RAPID code; refused at its name.
  VAR num x;
  PROC main()
    x := on_alarm();
  ENDPROC
  TRAP on_alarm
  ENDTRAP
ENDMODULE

MODULE trap_called_as_procedure
! @format 2
! @section 4.6
! @section 5.1
! @expect semantic-error 8:5
! @description A trap routine can never be called explicitly from RAPID code; refused at the name.
  PROC main()
    on_alarm;
  ENDPROC
  TRAP on_alarm
  ENDTRAP
ENDMODULE

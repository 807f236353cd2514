MODULE task_and_switch_are_identifiers
! @section 2.4
! @section 2.18
! @section 5.2
! @expect ok
! @description TASK and switch appear in the grammar but are not reserved words: they can be identifiers.
  VAR num TASK := 1;
  VAR num switch := 2;
  PROC main()
    TASK := switch + 1;
  ENDPROC
ENDMODULE

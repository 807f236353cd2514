MODULE entry_a
! @format 4
! @task T_ROB1
! @section 14
! @section 9.1
! @entry T_B=serve
! @expect ok
! @description Each task runs its own entry routine (@entry TASK=ROUTINE, rapid-sem run --entry TASK=ROUTINE); a task without one runs main. Both tasks declare a main, each in its own task buffer.
! @output A main
! @output B serve
  PROC main()
    TPWrite "A main";
  ENDPROC
ENDMODULE

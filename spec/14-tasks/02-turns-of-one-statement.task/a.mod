MODULE turns_a
! @format 4
! @task T_ROB1
! @section 14
! @expect ok
! @description Without @schedule the tasks take turns round robin, one statement a turn, in the order of the tasks (R-14-a).
! @output a1
! @output b1
! @output a2
! @output b2
! @output a3
  PROC main()
    TPWrite "a1";
    TPWrite "a2";
    TPWrite "a3";
  ENDPROC
ENDMODULE

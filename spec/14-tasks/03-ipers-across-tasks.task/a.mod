MODULE ipers_a
! @format 4
! @task T_ROB1
! @section 14
! @section 8
! @expect ok
! @description IPers in one task: a change of the system-global persistent by another task is a change of its value, and the interrupt's trap runs in the task that ordered it.
! @output B changes
! @output A trap 5
  VAR intnum changed;
  PERS num shared := 0;
  TRAP seen
    TPWrite "A trap " + NumToStr(shared, 0);
  ENDTRAP
  PROC main()
    CONNECT changed WITH seen;
    IPers shared, changed;
    WaitTime 1;
  ENDPROC
ENDMODULE

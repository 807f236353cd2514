MODULE task_pers_a
! @format 4
! @task T_ROB1
! @section 14
! @section 2.23
! @expect ok
! @description A TASK persistent is not system-global (ch. 14: objects declared TASK or LOCAL are not shared): each task has its own; a LOCAL one too.
! @output A wrote 2 and 20
! @output B reads 1 and 10
  TASK PERS num mine := 1;
  LOCAL PERS num here := 10;
  PROC main()
    mine := 2;
    here := 20;
    TPWrite "A wrote " + NumToStr(mine, 0) + " and " + NumToStr(here, 0);
  ENDPROC
ENDMODULE

MODULE mismatch_a
! @format 4
! @task T_ROB1
! @section 14
! @expect semantic-error b.mod:3:3
! @description ch. 14 shares a system-global persistent between the tasks that declare it with the same name and type: the same name with another type in a second task is refused at that declaration (R-14-c).
  PERS num state := 0;
  PROC main()
  ENDPROC
ENDMODULE

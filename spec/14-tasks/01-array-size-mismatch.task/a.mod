MODULE size_a
! @format 4
! @task T_ROB1
! @section 14
! @expect semantic-error b.mod:3:3
! @description The type of a system-global persistent includes its array sizes: num{2} in one task and num{3} in another are two types, refused at the later declaration (R-14-c).
  PERS num arr{2} := [1, 2];
  PROC main()
  ENDPROC
ENDMODULE

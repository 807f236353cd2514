MODULE first_value_a
! @format 4
! @task T_ROB1
! @section 14
! @expect ok
! @description ch. 14: the initial value of a system-global persistent is set only when its module is first loaded: of two declarations with values, the first task's wins; a declaration without one takes the value of a later task's declaration that has one.
! @output A tool 3 count 5
! @output B tool 3 count 5
  PERS num tool := 3;
  PERS num count;
  PROC main()
    TPWrite "A tool " + NumToStr(tool, 0) + " count " + NumToStr(count, 0);
  ENDPROC
ENDMODULE

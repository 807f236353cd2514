MODULE no_value_a
! @format 4
! @task T_ROB1
! @section 14
! @expect ok
! @description ch. 14: without any initial value a system-global persistent is initialised like a variable: state equals zero in every task.
! @output A 0 FALSE
! @output B 0 FALSE
  PERS num state;
  PERS bool flag;
  PROC main()
    TPWrite "A " + NumToStr(state, 0) + " " \Bool := flag;
  ENDPROC
ENDMODULE

MODULE same_label_in_two_routines
! @format 2
! @section 4.4
! @expect ok
! @description The scope of a label is its routine: two routines may use the same label name.
  VAR num i;
  PROC main()
    next:
    i := i + 1;
    IF i < 3 GOTO next;
  ENDPROC
  PROC other()
    next:
    i := i - 1;
    IF i > 0 GOTO next;
  ENDPROC
ENDMODULE

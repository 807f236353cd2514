MODULE two_labels_one_routine
! @format 2
! @section 4.4
! @expect semantic-error 10:7
! @description Two labels of the same routine may not share a name, even in different statement lists; the second is refused.
  VAR num i;
  PROC main()
    again:
    IF i > 0 THEN
      again:
      i := 0;
    ENDIF
  ENDPROC
ENDMODULE

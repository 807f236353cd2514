MODULE placeholder_eit_misplaced
! @section 2.9
! @expect syntax-error 8:5
! @description <EIT> belongs to an IF statement, not to TEST.
  VAR num x;
  PROC main()
    TEST x
    <EIT>
    ENDTEST
  ENDPROC
ENDMODULE

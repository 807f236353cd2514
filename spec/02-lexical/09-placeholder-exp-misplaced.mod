MODULE placeholder_exp_misplaced
! @section 2.9
! @expect syntax-error 7:14
! @description <EXP> stands for a whole <expression>, not for an operand inside one.
  VAR num x;
  PROC main()
    x := 1 + <EXP>;
  ENDPROC
ENDMODULE

MODULE refused_comparison_num_dnum
! @format 2
! @section 3.12
! @expect semantic-error 10:10
! @description >= compares two num or two dnum; num >= dnum is refused at the left operand.
  VAR num n;
  VAR dnum d;
  VAR bool r;
  PROC main()
    r := n >= d;
  ENDPROC
ENDMODULE

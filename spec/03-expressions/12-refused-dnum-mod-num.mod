MODULE refused_dnum_mod_num
! @format 2
! @section 3.12
! @expect semantic-error 10:10
! @description MOD takes two num or two dnum operands; dnum MOD num is refused at the left operand.
  VAR dnum d;
  VAR num k;
  VAR dnum r;
  PROC main()
    r := d MOD k;
  ENDPROC
ENDMODULE

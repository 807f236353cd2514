MODULE literal_beyond_num_initial
! @format 2
! @section 2.5
! @section 2.13
! @expect semantic-error 7:42
! @description The largest finite single is about 3.40282347E38: 3.4028235E38 rounds to it and is accepted, 3.5E38 rounds to infinity and is refused, here in a persistent's initial value.
  PERS num largest{2} := [3.4028235E38, -3.5E38];
  PROC main()
  ENDPROC
ENDMODULE

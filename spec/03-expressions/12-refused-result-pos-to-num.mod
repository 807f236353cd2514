MODULE refused_result_pos_to_num
! @format 2
! @section 3.12
! @section 4.5
! @expect semantic-error 11:10
! @description pos * pos gives a pos; assigning it to a num is refused at the right-hand side.
  VAR pos p1;
  VAR pos p2;
  VAR num r;
  PROC main()
    r := p1 * p2;
  ENDPROC
ENDMODULE

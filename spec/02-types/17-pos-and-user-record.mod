MODULE pos_and_user_record
! @format 2
! @section 2.17
! @expect semantic-error 14:10
! @description A user record with components x, y, z is not pos; refused at the right-hand side.
  RECORD vector
    num x;
    num y;
    num z;
  ENDRECORD
  VAR vector v;
  VAR pos p;
  PROC main()
    p := v;
  ENDPROC
ENDMODULE

MODULE initialiser_persistent
! @format 2
! @section 2.22
! @section 3.2
! @expect semantic-error 8:16
! @description A constant expression may not contain a persistent; refused at the persistent.
  PERS num p := 1;
  VAR num b := p + 1;
ENDMODULE

MODULE feeder
! @format 2
! @section 9.2
! @expect semantic-error 6:11
! @description A module and a global module object may not share a name; the data object, which comes second, is refused.
  VAR num feeder;
ENDMODULE

MODULE placeholder_tdn
! @section 2.9
! @section 2.11
! @expect ok
! @description <TDN> stands for a type definition.
  <TDN>
  VAR num x;
ENDMODULE

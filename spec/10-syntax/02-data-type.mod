MODULE data_type
! @section 2.11
! @expect ok
! @description <data type> ::= <identifier>: any identifier, or <ID>.
  VAR num a;
  VAR robtarget b;
  VAR <ID> c;
  VAR my_own_type d;
ENDMODULE

MODULE identifier_forms
! @section 2.3
! @expect ok
! @description An identifier is a letter followed by letters, digits and underscores.
  VAR num a;
  VAR num a1;
  VAR num a_b_1;
  VAR num Z__;
  VAR num x9_;
  VAR num Go_2_Home;
ENDMODULE

MODULE attributes_viewonly_before_noste(VIEWONLY, NOSTEPIN)
! @format 2
! @section 9.2
! @expect semantic-error 1:51
! @description Attributes must be given in the order of the table: NOSTEPIN after VIEWONLY is refused.
  VAR num n;
ENDMODULE

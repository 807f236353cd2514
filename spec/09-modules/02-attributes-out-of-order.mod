MODULE attributes_out_of_order(NOSTEPIN, SYSMODULE)
! @format 2
! @section 9.2
! @expect semantic-error 1:42
! @description Attributes must be given in the order of the table: SYSMODULE after NOSTEPIN is refused.
  VAR num n;
ENDMODULE

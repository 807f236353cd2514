MODULE noview_excludes_nostepin(NOVIEW, NOSTEPIN)
! @format 2
! @section 9.2
! @expect semantic-error 1:41
! @description NOVIEW excludes NOSTEPIN; refused at NOSTEPIN.
  VAR num n;
ENDMODULE

MODULE nostepin_excludes_noview(NOSTEPIN, NOVIEW)
! @format 2
! @section 9.2
! @expect semantic-error 1:43
! @description NOSTEPIN excludes NOVIEW (and stands after it in the table); refused at NOVIEW.
  VAR num n;
ENDMODULE

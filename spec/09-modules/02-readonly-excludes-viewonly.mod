MODULE readonly_excludes_viewonly(READONLY, VIEWONLY)
! @format 2
! @section 9.2
! @expect semantic-error 1:45
! @description READONLY excludes VIEWONLY (and stands after it in the table); refused at VIEWONLY.
  VAR num n;
ENDMODULE

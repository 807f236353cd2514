MODULE noview_excludes_viewonly(SYSMODULE, NOVIEW, VIEWONLY)
! @format 2
! @section 9.2
! @expect semantic-error 1:52
! @description NOVIEW excludes VIEWONLY; refused at VIEWONLY.
  VAR num n;
ENDMODULE

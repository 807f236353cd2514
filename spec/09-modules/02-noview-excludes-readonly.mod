MODULE noview_excludes_readonly(NOVIEW, READONLY)
! @format 2
! @section 9.2
! @expect semantic-error 1:41
! @description NOVIEW excludes READONLY; refused at READONLY.
  VAR num n;
ENDMODULE

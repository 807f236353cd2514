MODULE viewonly_excludes_readonly(VIEWONLY, READONLY)
! @format 2
! @section 9.2
! @expect semantic-error 1:45
! @description VIEWONLY excludes READONLY; refused at READONLY.
  VAR num n;
ENDMODULE

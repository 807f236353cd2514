MODULE predefined_without_hiding
! @format 2
! @section 2.19
! @section 2.20
! @section 2.17
! @expect semantic-error 9:13
! @description Without a module object of that name, ERR_NOTPRES is the predefined errnum constant: TPWrite refuses it at the argument.
  PROC main()
    TPWrite ERR_NOTPRES;
  ENDPROC
ENDMODULE

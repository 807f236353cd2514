MODULE (SYSMODULE)
! @section 9.2
! @expect syntax-error 1:8
! @description MODULE <module name>: the name may not be left out.
ENDMODULE

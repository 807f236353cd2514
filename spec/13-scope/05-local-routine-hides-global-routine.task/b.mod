MODULE cell
! @format 2
! @section 5.3
! @expect ok
! @description A LOCAL routine hides a global routine of the same name from another module: report takes a num in b.
  LOCAL PROC report(num code)
  ENDPROC
  PROC main()
    report 5;
  ENDPROC
ENDMODULE

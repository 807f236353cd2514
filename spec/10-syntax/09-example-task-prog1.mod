MODULE prog1(SYSMODULE, VIEWONLY)
! @section 9.2
! @expect ok
! @description The first module of the task of section 9.2.
  PROC main()
  ! init weldlib
  initweld;
  FOR i FROM 1 TO Dim(posearr,1) DO
    slow posearr{i};
  ENDFOR
  ENDPROC
  PROC slow(pose p)
    arcweld p \speed := 25;
  ENDPROC
ENDMODULE

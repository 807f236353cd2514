MODULE prog1(SYSMODULE, VIEWONLY)
! @format 2
! @section 9.2
! @section 9.1
! @expect ok
! @description Section 9.2's task prog1, weldlib and weldpath; welddata, sysw1 and the 768 poses are replaced by a small record, a constant and two poses.
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

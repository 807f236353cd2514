MODULE weldlib
! @section 9.2
! @expect ok
! @description The second module of the task of section 9.2 (its elided arcweld body left empty).
  LOCAL VAR welddata w1 := sysw1;
  ! weldlib init procedure
  PROC initweld()
    ! override speed
    w1.speed := 100;
  ENDPROC
  PROC arcweld(pose position \ num speed | num time)
  ENDPROC
ENDMODULE

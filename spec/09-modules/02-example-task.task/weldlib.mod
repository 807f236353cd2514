MODULE weldlib
  RECORD welddata
    num speed;
    num current;
  ENDRECORD
  CONST welddata sysw1 := [10, 150];
  LOCAL VAR welddata w1 := sysw1;
  ! weldlib init procedure
  PROC initweld()
    ! override speed
    w1.speed := 100;
  ENDPROC
  PROC arcweld(pose position \num speed | num time)
  ENDPROC
ENDMODULE

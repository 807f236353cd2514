MODULE Log
  ! A STATIC state server: it runs the POWER_ON routine only, then reads the moving robot's
  ! joints (the motion task of its mechanical unit group).
  PERS bool cycle_done;
  PERS num phase;

  PROC power_on()
    TPWrite "log: power on";
  ENDPROC

  PROC logger()
    VAR jointtarget j;
    j := CJointT();
    WHILE j.robax.rax_1 <= 15 DO
      WaitTime 0.05;
      j := CJointT();
    ENDWHILE
    TPWrite "log: axis 1 passed 15 degrees in phase " \Num:=phase;
    WaitUntil cycle_done;
    j := CJointT();
    TPWrite "log: axis 1 at " \Num:=Round(j.robax.rax_1);
  ENDPROC

  PROC on_stop()
    TPWrite "log: stop (a STATIC task: never)";
  ENDPROC
ENDMODULE

MODULE State
  ! A state server: a task without a robot of its own reads the robot of its mechanical unit
  ! group's motion task.
  PERS bool cell_done;
  PERS num cell_cycles;

  PROC serve()
    VAR jointtarget j;
    j := CJointT();
    WHILE j.robax.rax_1 <= 20 DO
      WaitTime 0.05;
      j := CJointT();
    ENDWHILE
    TPWrite "state: axis 1 passed 20 degrees";
    WaitUntil cell_done;
    j := CJointT();
    TPWrite "state: axis 1 at " \Num:=Round(j.robax.rax_1);
    TPWrite "state: cycles " \Num:=cell_cycles;
  ENDPROC
ENDMODULE

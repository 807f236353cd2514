MODULE state_b
! @task ROS_STATE
  VAR clock c;
  VAR taskid nobody;

  FUNC string axis6(jointtarget j)
    RETURN NumToStr(Round(j.robax.rax_6), 0);
  ENDFUNC

  FUNC string xyz(pos p)
    RETURN NumToStr(Round(p.x), 0) + " " + NumToStr(Round(p.y), 0) + " " + NumToStr(Round(p.z), 0);
  ENDFUNC

  PROC refused(num k)
    VAR jointtarget j;
    IF k = 1 THEN
      j := CJointT(\TaskName:="NOWHERE");
    ELSE
      j := CJointT(\TaskRef:=nobody);
    ENDIF
    TPWrite "B: not reached";
  ERROR
    IF ERRNO = ERR_TASKNAME TPWrite "B: ERR_TASKNAME";
    RETURN;
  ENDPROC

  PROC main()
    VAR jointtarget j;
    VAR robtarget r;
    ClkStart c;
    FOR i FROM 1 TO 5 DO
      WaitTime 0.1;
      j := CJointT();
      TPWrite "B: t " + NumToStr(Round(1000 * ClkRead(c)), 0) + " axis 6 " + axis6(j);
    ENDFOR
    WaitTime 0.2;
    TPWrite "B: T_ROB1's axis 6 " + axis6(CJointT(\TaskName:="T_ROB1"));
    TPWrite "B: its own name's axis 6 " + axis6(CJointT(\TaskName:="ros_state"));
    r := CRobT(\Tool:=tool0);
    TPWrite "B: CRobT " + xyz(r.trans);
    TPWrite "B: CPos " + xyz(CPos(\Tool:=tool0 \WObj:=wobj0));
    refused 1;
    refused 2;
  ENDPROC
ENDMODULE

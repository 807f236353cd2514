MODULE base_frames_b
! @task T_ROB2
  PERS bool a_done;
  CONST jointtarget home := [[0,0,0,0,90,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget pb := [[-50,-100,1300],[0,1,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    VAR robtarget r;
    VAR robtarget s;
    MoveAbsJ home, v1000, fine, tool0;
    r := CRobT(\Tool:=tool0);
    ConfL \Off;
    MoveL pb, v200, fine, tool0;
    s := CRobT(\Tool:=tool0);
    WaitUntil a_done;
    TPWrite "B home " + NumToStr(r.trans.x, 0) + " " + NumToStr(r.trans.y, 0) + " " + NumToStr(r.trans.z, 0);
    TPWrite "B at " + NumToStr(s.trans.x, 0) + " " + NumToStr(s.trans.y, 0) + " " + NumToStr(s.trans.z, 0);
  ENDPROC
ENDMODULE

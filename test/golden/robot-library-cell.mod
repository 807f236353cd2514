MODULE robot_library_cell
  ! A cell of an IRB 2400 (MOC.cfg robot type ROB1_2400_1.5_10): targets beyond an IRB 120's reach.
  CONST robtarget p1 := [[1200,0,1000],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p2 := [[1200,300,800],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    VAR robtarget r;
    MoveJ p1, v1000, fine, tool0;
    MoveL p2, v500, z10, tool0;
    MoveL p1, v500, fine, tool0;
    r := CRobT(\Tool:=tool0);
    TPWrite "at x " + NumToStr(r.trans.x, 1) + " y " + NumToStr(r.trans.y, 1) + " z " + NumToStr(r.trans.z, 1);
  ENDPROC
ENDMODULE

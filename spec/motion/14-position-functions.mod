MODULE position_functions
! @format 3
! @section 13
! @expect ok
! @description Offs displaces in the object frame, RelTool in the tool frame (the tool's z points down with [0,0,1,0]); CalcJointT gives the axis angles of a robtarget and CalcRobT the robtarget of axis angles; a target out of reach with \ErrorNumber sets ERR_ROBLIMIT instead of raising it (installed-facts.md section 4).
! @output Offs [300,250,400]
! @output RelTool [300,250,200]
! @output axis 1 40
! @output CalcRobT 300.0 250.0 300.0
! @output ERR_ROBLIMIT TRUE
  CONST robtarget p2 := [[300,250,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    VAR jointtarget j;
    VAR robtarget r;
    VAR errnum err := 0;
    r := Offs(p2, 0, 0, 100);
    TPWrite "Offs " \Pos:=r.trans;
    r := RelTool(p2, 0, 0, 100);
    TPWrite "RelTool " \Pos:=r.trans;
    j := CalcJointT(p2, tool0);
    TPWrite "axis 1 " \Num:=Round(j.robax.rax_1);
    r := CalcRobT(j, tool0);
    TPWrite "CalcRobT " + NumToStr(r.trans.x, 1) + " " + NumToStr(r.trans.y, 1) + " " + NumToStr(r.trans.z, 1);
    j := CalcJointT(Offs(p2, 2000, 0, 0), tool0 \ErrorNumber:=err);
    TPWrite "ERR_ROBLIMIT " \Bool:=(err = ERR_ROBLIMIT);
  ENDPROC
ENDMODULE

MODULE sig_cell
! @format 2
! @section 13
! @section 4.6
! @expect ok
! @description Installed routines of cell programs declared in cell.sys (doc/rulings.md R-13-x): the RAPID Message Queue (rmqslot, rmqmessage, rmqheader, RMQFindSlot, RMQSendMessage, IRMQMessage, RMQGetMessage, RMQGetMsgHeader, RMQGetMsgData, RMQReadWait, RMQEmptyQueue, RMQGetSlotName), TriggInt and TriggC, CirPathMode, SetSysData, the mechanical-unit routines, ModExist, and world zones (shapedata, wztemporary, wzstationary, WZBoxDef, WZCylDef, WZSphDef, WZHomeJointDef, WZLimJointDef, WZLimSup, WZDOSet, WZEnable, WZDisable, WZFree), called as ABB documents them.
  VAR rmqslot peer;
  VAR rmqmessage inbox;
  VAR rmqheader head;
  VAR intnum onData;
  VAR triggdata halfway;
  VAR num reading;
  VAR wztemporary keepOut;
  VAR wzstationary cellFence;
  VAR signaldo doInZone;
  PERS tooldata tTorch := [TRUE,[[0,0,200],[1,0,0,0]],[2,[0,0,80],[1,0,0,0],0,0,0]];
  CONST robtarget k1 := [[300,0,400],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget k2 := [[350,50,400],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    VAR num unit := 0;
    VAR string uname;
    VAR num axes;
    RMQFindSlot peer, "RMQ_T_ROB2";
    RMQSendMessage peer, reading \UserDef:=7;
    CONNECT onData WITH Received;
    IRMQMessage reading, onData;
    RMQReadWait inbox \TimeOut:=2;
    RMQEmptyQueue;
    TPWrite RMQGetSlotName(peer);
    TriggInt halfway, 10 \Start, onData;
    TriggInt halfway, 0.2 \Time, onData;
    TriggC k1, k2, v100, halfway, z10, tTorch;
    CirPathMode \Wrist45;
    CirPathMode;
    SetSysData tTorch;
    SetSysData tool0 \ObjectName:="tTorch";
    WHILE GetNextMechUnit(unit, uname \NoOfAxes:=axes) DO
      TPWrite uname;
    ENDWHILE
    IF IsMechUnitActive(ROB_1) TPWrite GetMecUnitName(ROB_1 \UseGenericName);
    DeactUnit ROB_1;
    ActUnit ROB_1;
    IF NOT ModExist("sig_cell") TPWrite "missing";
    Zones;
  ENDPROC
  PROC Zones()
    VAR shapedata box;
    VAR shapedata cyl;
    VAR shapedata ball;
    VAR shapedata axes;
    CONST pos lo := [-500, -500, 0];
    CONST pos hi := [500, 500, 1000];
    CONST jointtarget mid := [[0, 0, 0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
    CONST jointtarget delta := [[5, 5, 5, 5, 5, 5], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
    WZBoxDef \Outside, box, lo, hi;
    WZCylDef \Inside, cyl, [0, 0, 0], 200, 800;
    WZSphDef \Inside, ball, [300, 0, 500], 50;
    WZHomeJointDef \Inside, axes, mid, delta;
    WZLimJointDef \Outside, axes, mid, delta;
    WZLimSup \Stat, cellFence, box;
    WZLimSup \Temp, keepOut, cyl;
    WZDOSet \Temp, keepOut \Inside, ball, doInZone, 1;
    WZDisable keepOut;
    WZEnable keepOut;
    WZFree keepOut;
  ENDPROC
  TRAP Received
    RMQGetMessage inbox;
    RMQGetMsgHeader inbox \Header:=head \SenderId:=peer;
    IF head.datatype = "num" RMQGetMsgData inbox, reading;
  ENDTRAP
ENDMODULE

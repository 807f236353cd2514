MODULE sig_trigg
! @format 2
! @section 13
! @section 4.6
! @expect ok
! @description The path triggers as ABB documents them (motion.sys, cell.sys; R-4.1-trigg1): TriggIO (\Start or \Time, \DOp, \GOp or \AOp, a num or dnum SetValue, \DODelay), TriggEquip (EquipLag, \Inhib), TriggInt, TriggSpeed (ScaleLag, ScaleValue, \DipLag, \ErrDO, \Inhib), TriggCheckIO (Relation, \StopMove) and TriggRampAO, and the moves TriggL, TriggJ, TriggC with up to eight triggdata (Trigg_1, \T2 to \T8), \Conc, \T, \Inpos, \WObj, \Corr, \TLoad.
  VAR signaldo doGun;
  VAR signalgo goCode;
  VAR signalao aoFlow;
  VAR signaldi diOk;
  VAR intnum check;
  VAR intnum pos;
  PERS bool gunInhib := FALSE;
  VAR triggdata t1;
  VAR triggdata t2;
  VAR triggdata t3;
  VAR triggdata t4;
  VAR triggdata t5;
  VAR triggdata t6;
  VAR triggdata t7;
  VAR triggdata t8;
  VAR dnum big := 65535;
  CONST robtarget p1 := [[400,0,400],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p2 := [[400,100,400],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    TriggIO t1, 10 \Start \DOp:=doGun, 1;
    TriggIO t2, 0.1 \Time \GOp:=goCode, big;
    TriggIO t3, 5 \AOp:=aoFlow, 2.5 \DODelay:=0.05;
    TriggEquip t4, 10 \Start, 0.05 \DOp:=doGun, 0 \Inhib:=gunInhib;
    TriggInt t5, 20, pos;
    TriggSpeed t6, 0 \Start, 0.05, aoFlow, 0.01 \DipLag:=0.05 \ErrDO:=doGun \Inhib:=gunInhib;
    TriggCheckIO t7, 30, diOk, EQ, 1 \StopMove, check;
    TriggRampAO t8, 10 \Start, 0.05, aoFlow, 5, 20;
    TriggL p1, v100, t1 \T2:=t2 \T3:=t3 \T4:=t4 \T5:=t5 \T6:=t6 \T7:=t7 \T8:=t8, z10, tool0;
    TriggL \Conc, p2, v100 \T:=2, t1, fine \Inpos:=inpos20, tool0 \WObj:=wobj0 \Corr \TLoad:=load0;
    TriggJ p1, v100, t1 \T2:=t5, fine, tool0;
    TriggC p2, p1, v100, t1, z10, tool0 \WObj:=wobj0;
  ENDPROC
ENDMODULE

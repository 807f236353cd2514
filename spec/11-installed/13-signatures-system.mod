MODULE sig_system
! @format 2
! @section 13
! @section 4.6
! @expect ok
! @description The system routines as ABB documents them: OpMode and the OP_ constants, RunMode and the RUN_ constants, RobOS, GetSysInfo with each switch, GetTaskName with \TaskNo or \MecTaskNo, IsSysId, GetDataVal and SetDataVal with \TaskName, ReadCfgData and WriteCfgData with \ListNo, WaitTestAndSet on a persistent, AliasIO from a configuration name and from a signal, Load and UnLoad, WaitSyncTask, SyncMoveOn and SyncMoveOff with tasks and syncident, ReadErrData with \Title and \Str1..\Str5, and pi.
  PERS bool lock := FALSE;
  PERS tasks others{2} := [["T_ROB1"], ["T_ROB2"]];
  VAR syncident meet;
  VAR syncident coord;
  VAR signaldo doLamp;
  VAR signaldo doAlias;
  VAR trapdata event;
  VAR errdomain domain;
  VAR errtype kind;
  VAR num id;
  VAR num taskNo;
  VAR num listNo;
  VAR num speed;
  VAR string title;
  VAR string s1;
  VAR string s2;
  VAR string s3;
  VAR string s4;
  VAR string s5;
  VAR string info;
  PROC main()
    IF OpMode() = OP_AUTO OR OpMode() = OP_MAN_PROG OR OpMode() = OP_MAN_TEST THEN
      info := GetSysInfo(\SerialNo) + GetSysInfo(\SWVersion) + GetSysInfo(\RobotType);
    ENDIF
    IF RunMode() = RUN_CONT_CYCLE OR RunMode(\Main) = RUN_STEP_MOVE info := GetSysInfo(\CtrlId);
    IF RobOS() AND IsSysId("6400-1234") info := GetSysInfo(\LanIp) + GetSysInfo(\SystemName);
    info := GetTaskName() + GetTaskName(\TaskNo:=taskNo) + GetTaskName(\MecTaskNo:=taskNo);
    GetDataVal "speed" \TaskName:="T_ROB1", speed;
    SetDataVal "speed", speed;
    ReadCfgData "/MOC/MOTOR_CALIB/rob1_1", "cal_offset", speed \ListNo:=listNo;
    WriteCfgData "/MOC/MOTOR_CALIB/rob1_1", "cal_offset", speed * pi / 180;
    WaitTestAndSet lock;
    lock := FALSE;
    AliasIO "DO_LAMP", doAlias;
    AliasIO doLamp, doAlias;
    Load \Dynamic, "HOME:/part.mod" \CheckRef;
    UnLoad \Save, "HOME:" \File:="part.mod";
    WaitSyncTask \InPos, meet, others \TimeOut:=60;
    SyncMoveOn coord, others \TimeOut:=10;
    IF IsSyncMoveOn() SyncMoveOff coord \TimeOut:=10;
    ReadErrData event, domain, id, kind \Title:=title \Str1:=s1 \Str2:=s2 \Str3:=s3
      \Str4:=s4 \Str5:=s5;
  ERROR
    IF ERRNO = ERR_WAITSYNCTASK OR ERRNO = ERR_ALIASIO_DEF OR ERRNO = ERR_LOADED
        OR ERRNO = ERR_UNLOAD OR ERRNO = ERR_SYM_ACCESS OR ERRNO = ERR_CFG_NOTFND THEN
      TRYNEXT;
    ENDIF
  ENDPROC
ENDMODULE

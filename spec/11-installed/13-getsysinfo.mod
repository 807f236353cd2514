MODULE get_sys_info
! @format 3
! @section 13
! @expect ok
! @description GetSysInfo (ABB's RAPID reference, GetSysInfo: \SerialNo | \SWVersion | \SWVersionName | \RobotType | \CtrlId | \LanIp | \CtrlLang | \SystemName, a string) answers as rapid-sem's virtual controller (doc/rulings.md R-13-sys1): the serial number rapid-sem-vc, RobotWare 7.12.0 (the kernel manual's release), the robot type of the run's robot description (the default IRB 120), the controller and system rapid-sem, the loopback address where its sockets serve, the language en. Without a switch nothing is asked: ERR_ARGVALERR at the call.
! @output serial rapid-sem-vc
! @output version 7.12.0
! @output version name RobotWare 7.12.0
! @output robot ABB IRB 120
! @output controller rapid-sem
! @output address 127.0.0.1
! @output language en
! @output system rapid-sem
! @output no switch ERR_ARGVALERR
  VAR string info;
  PROC main()
    TPWrite "serial " + GetSysInfo(\SerialNo);
    TPWrite "version " + GetSysInfo(\SWVersion);
    TPWrite "version name " + GetSysInfo(\SWVersionName);
    TPWrite "robot " + GetSysInfo(\RobotType);
    TPWrite "controller " + GetSysInfo(\CtrlId);
    TPWrite "address " + GetSysInfo(\LanIp);
    TPWrite "language " + GetSysInfo(\CtrlLang);
    TPWrite "system " + GetSysInfo(\SystemName);
    info := GetSysInfo();
    TPWrite "no switch, no error";
  ERROR
    IF ERRNO = ERR_ARGVALERR TPWrite "no switch ERR_ARGVALERR";
    RETURN;
  ENDPROC
ENDMODULE

MODULE sysun1(SYSMODULE)
! @section 9.3
! @expect ok
! @description The system module of section 9.3, its elided aggregates completed.
  ! Provide predefined variables
  VAR num n1 := 0;
  VAR num n2 := 0;
  VAR num n3 := 0;
  VAR pos p1 := [0, 0, 0];
  VAR pos p2 := [0, 0, 0];
  ! Define channels - open in init function
  VAR channel printer;
  VAR channel logfile;
  ! Define standard tools
  PERS pose bmtool := [[0, 0, 0], [1, 0, 0, 0]];
  ! Define basic weld data records
  PERS wdrec wd1 := [0, 0];
  ! Define basic move data records
  PERS mvrec mv1 := [0, 0];
  ! Define home position - Sync. Pos. 3
  PERS robtarget home := [[0, 0, 0], [1, 0, 0, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  ! Init procedure
  LOCAL PROC init()
    Open\write, printer, "/dev/lpr";
    Open\write, logfile, "/usr/pm2/log1";
  ENDPROC
ENDMODULE

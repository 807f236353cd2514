MODULE aliasio_case
! @format 3
! @section 13
! @section 2.16
! @expect ok
! @io io/basic.io
! @statement-time 0
! @description AliasIO connects a signal variable of the program to a signal of the I/O configuration, named by a string or by the signal itself; a name the configuration does not have raises ERR_ALIASIO_DEF, a signal of another kind ERR_ALIASIO_TYPE.
! @output mydi seen at 1000
! @output do1=1
! @output ERR_ALIASIO_DEF TRUE
! @output ERR_ALIASIO_TYPE TRUE
  VAR signaldi mydi;
  VAR signaldo mydo;
  VAR string name := "DI1";
  VAR string missing := "di_nowhere";
  VAR clock c;
  PROC main()
    ClkStart c;
    AliasIO name, mydi;
    WaitDI mydi, 1;
    TPWrite "mydi seen at " \Num:=Round(ClkRead(c) * 1000);
    AliasIO do1, mydo;
    SetDO mydo, 1;
    TPWrite "do1=" \Num:=DOutput(do1);
    AliasIO missing, mydi;
    AliasIO di2, mydo;
  ERROR
    IF ERRNO = ERR_ALIASIO_DEF THEN
      TPWrite "ERR_ALIASIO_DEF TRUE";
    ELSEIF ERRNO = ERR_ALIASIO_TYPE THEN
      TPWrite "ERR_ALIASIO_TYPE TRUE";
    ENDIF
    TRYNEXT;
  ENDPROC
ENDMODULE

MODULE readnum_case
! @format 3
! @section 13
! @expect ok
! @description ReadNum reads a line (or a field up to \Delim) as a number; a field that is not a number raises ERR_RCVDATA; at the end of the file it returns EOF_NUM.
! @output first 12.5
! @output second -3
! @output third 7
! @output ERR_RCVDATA
! @output EOF_NUM
! @exit 0
  VAR iodev file;
  VAR num n;
  PROC main()
    Open "HOME:/numbers.txt", file \Write;
    Write file, "12.5";
    Write file, "-3 7";
    Write file, "seven";
    Close file;
    Open "HOME:/numbers.txt", file \Read;
    TPWrite "first " \Num:=ReadNum(file);
    TPWrite "second " \Num:=ReadNum(file \Delim:=" ");
    TPWrite "third " \Num:=ReadNum(file);
    n := ReadNum(file);
    TPWrite "not reached";
  ERROR
    IF ERRNO = ERR_RCVDATA THEN
      TPWrite "ERR_RCVDATA";
      n := ReadNum(file);
      IF n = EOF_NUM TPWrite "EOF_NUM";
      Close file;
      RETURN;
    ENDIF
  ENDPROC
ENDMODULE

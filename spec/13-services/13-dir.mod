MODULE dir_case
! @format 3
! @section 13
! @expect ok
! @description OpenDir opens a directory, ReadDir gives the name of each entry in turn ("." and ".." first, then the names in order) and FALSE after the last, CloseDir closes it; a directory that does not exist raises ERR_FILEACC.
! @output .
! @output ..
! @output a.txt
! @output b.txt
! @output sub
! @output ERR_FILEACC
! @exit 0
  VAR dir d;
  VAR string name;
  VAR iodev file;
  PROC main()
    MakeDir "TEMP:/list";
    MakeDir "TEMP:/list/sub";
    Open "TEMP:/list/b.txt", file \Write;
    Close file;
    Open "TEMP:/list/a.txt", file \Write;
    Close file;
    OpenDir d, "TEMP:/list";
    WHILE ReadDir(d, name) DO
      TPWrite name;
    ENDWHILE
    CloseDir d;
    OpenDir d, "TEMP:/nowhere";
    TPWrite "not reached";
  ERROR
    IF ERRNO = ERR_FILEACC TPWrite "ERR_FILEACC";
    RETURN;
  ENDPROC
ENDMODULE

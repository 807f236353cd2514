MODULE file_system
! @format 3
! @section 13
! @expect ok
! @description IsFile (with \Directory and \RegFile), FileSize, MakeDir, CopyFile, RenameFile, RemoveFile and RemoveDir on the sandboxed devices, with their errors: ERR_FILEEXIST for a directory or target that exists, ERR_FILEACC for a file that does not exist or a directory that is not empty.
! @output directory TRUE
! @output regular FALSE
! @output exists TRUE
! @output size 4
! @output copied 4
! @output renamed away FALSE
! @output renamed to TRUE
! @output ERR_FILEEXIST
! @output ERR_FILEEXIST
! @output ERR_FILEACC
! @output ERR_FILEACC
! @output ERR_FILEACC
! @output ERR_FILEACC
! @output removed FALSE
! @exit 0
  VAR iodev file;
  PROC main()
    MakeDir "HOME:/work";
    TPWrite "directory " \Bool:=IsFile("HOME:/work" \Directory);
    TPWrite "regular " \Bool:=IsFile("HOME:/work" \RegFile);
    Open "HOME:/work/a.txt", file \Write;
    Write file, "abc";
    Close file;
    TPWrite "exists " \Bool:=IsFile("HOME:/work/a.txt");
    TPWrite "size " \Num:=FileSize("HOME:/work/a.txt");
    CopyFile "HOME:/work/a.txt", "TEMP:/b.txt";
    TPWrite "copied " \Num:=FileSize("TEMP:/b.txt");
    RenameFile "TEMP:/b.txt", "HOME:/work/c.txt";
    TPWrite "renamed away " \Bool:=IsFile("TEMP:/b.txt");
    TPWrite "renamed to " \Bool:=IsFile("HOME:/work/c.txt");
    TPWrite Attempt(1);
    TPWrite Attempt(2);
    TPWrite Attempt(3);
    TPWrite Attempt(4);
    TPWrite Attempt(5);
    TPWrite Attempt(6);
    RemoveFile "HOME:/work/a.txt";
    RemoveFile "HOME:/work/c.txt";
    RemoveDir "HOME:/work";
    TPWrite "removed " \Bool:=IsFile("HOME:/work");
  ENDPROC

  FUNC string Attempt(num what)
    VAR num size;
    TEST what
    CASE 1:
      MakeDir "HOME:/work";
    CASE 2:
      CopyFile "HOME:/work/a.txt", "HOME:/work/c.txt";
    CASE 3:
      RenameFile "HOME:/missing.txt", "HOME:/other.txt";
    CASE 4:
      size := FileSize("HOME:/missing.txt");
    CASE 5:
      RemoveFile "HOME:/missing.txt";
    CASE 6:
      RemoveDir "HOME:/work";
    ENDTEST
    RETURN "no error";
  ERROR
    IF ERRNO = ERR_FILEEXIST RETURN "ERR_FILEEXIST";
    IF ERRNO = ERR_FILEACC RETURN "ERR_FILEACC";
  ENDFUNC
ENDMODULE

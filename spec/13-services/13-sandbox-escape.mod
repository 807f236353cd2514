MODULE sandbox_escape
! @format 3
! @section 13
! @expect ok
! @description No path leads out of the controller's devices: a ".." component, a host path without a device and a device the controller does not have are refused with the routine's file error (ERR_FILEOPEN for Open, ERR_FILEACC for the others), whether or not the host file exists.
! @output ERR_FILEOPEN
! @output ERR_FILEOPEN
! @output ERR_FILEOPEN
! @output ERR_FILEACC
! @output ERR_FILEACC
! @output ERR_FILEACC
! @output ERR_FILEACC
! @output ERR_FILEACC
! @output ERR_FILEACC
! @exit 0
  VAR iodev file;
  VAR dir d;
  PROC main()
    TPWrite Attempt(1);
    TPWrite Attempt(2);
    TPWrite Attempt(3);
    TPWrite Attempt(4);
    TPWrite Attempt(5);
    TPWrite Attempt(6);
    TPWrite Attempt(7);
    TPWrite Attempt(8);
    TPWrite Attempt(9);
  ENDPROC

  FUNC string Attempt(num what)
    VAR bool b;
    VAR num n;
    TEST what
    CASE 1:
      Open "HOME:/../../../../../../../etc/passwd", file \Read;
    CASE 2:
      Open "/etc/passwd", file \Read;
    CASE 3:
      Open "HOME:" \File:="../escape.txt", file \Write;
    CASE 4:
      b := IsFile("/etc/passwd");
    CASE 5:
      n := FileSize("TEMP:/a/../../HOME/x.txt");
    CASE 6:
      OpenDir d, "HOME:/..";
    CASE 7:
      CopyFile "/etc/passwd", "HOME:/passwd";
    CASE 8:
      RemoveFile "C:/Windows/win.ini";
    CASE 9:
      MakeDir "HOME:/../outside";
    ENDTEST
    RETURN "no error";
  ERROR
    IF ERRNO = ERR_FILEOPEN RETURN "ERR_FILEOPEN";
    IF ERRNO = ERR_FILEACC RETURN "ERR_FILEACC";
  ENDFUNC
ENDMODULE

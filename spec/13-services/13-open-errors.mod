MODULE open_errors
! @format 3
! @section 13
! @expect ok
! @description Open raises ERR_FILEOPEN for a file that cannot be opened (missing for reading, an unknown device, a directory, an iodev already open); Write, ReadStr and the other routines raise ERR_FILEACC on a device that is not open or not open that way; Close of a closed device does nothing.
! @output ERR_FILEOPEN
! @output ERR_FILEOPEN
! @output ERR_FILEOPEN
! @output ERR_FILEACC
! @output ERR_FILEACC
! @output ERR_FILEOPEN
! @output ERR_FILEACC
! @output ERR_FILEACC
! @output closed twice
! @exit 0
  VAR iodev file;
  VAR iodev other;
  VAR string s;
  PROC main()
    TPWrite Attempt(1);
    TPWrite Attempt(2);
    TPWrite Attempt(3);
    TPWrite Attempt(4);
    TPWrite Attempt(5);
    TPWrite Attempt(6);
    TPWrite Attempt(7);
    TPWrite Attempt(8);
    Close file;
    Close file;
    TPWrite "closed twice";
  ENDPROC

  FUNC string Attempt(num what)
    TEST what
    CASE 1:
      Open "HOME:/missing.txt", file \Read;
    CASE 2:
      Open "NOWHERE:/a.txt", file \Write;
    CASE 3:
      MakeDir "HOME:/folder";
      Open "HOME:/folder", file \Write;
    CASE 4:
      Write other, "never open";
    CASE 5:
      Open "HOME:/a.txt", file \Write;
      s := ReadStr(file);
    CASE 6:
      Open "HOME:/a.txt", file \Write;
    CASE 7:
      Close file;
      Open "HOME:/a.txt", file \Read;
      Write file, "read only";
    CASE 8:
      Close file;
      s := ReadStr(file);
    ENDTEST
    RETURN "no error";
  ERROR
    IF ERRNO = ERR_FILEOPEN RETURN "ERR_FILEOPEN";
    IF ERRNO = ERR_FILEACC RETURN "ERR_FILEACC";
  ENDFUNC
ENDMODULE

MODULE sig_files
! @format 2
! @section 13
! @section 4.6
! @expect ok
! @description The file routines as ABB documents them: Open with \Bin combined with \Read, \Write or \Append; Write, WriteBin, WriteStrBin, WriteAnyBin, WriteRawBytes; ReadStr with \Delim \RemoveCR \DiscardHeaders \Time \Line, ReadNum, ReadBin, ReadStrBin, ReadAnyBin, ReadRawBytes; the file system (IsFile, FileSize, MakeDir, RemoveDir, RemoveFile, RenameFile, CopyFile, OpenDir, ReadDir, CloseDir); EOF and the file errors.
  VAR iodev log;
  VAR iodev bin;
  VAR dir folder;
  VAR rawbytes raw;
  VAR string line;
  VAR string name;
  VAR num value;
  VAR num codes{3} := [65, 66, 10];
  VAR pos where;
  PROC main()
    Open "HOME:" \File:="log.txt", log \Append;
    Open "HOME:/data.bin", bin \Read \Bin;
    Open "HOME:/out.bin", bin \Write \Bin;
    Open "HOME:/copy.bin", bin \Bin;
    Write log, "value: " \Num:=value \NoNewLine;
    Write log, "at " \Pos:=where;
    WriteBin bin, codes, 3;
    WriteStrBin bin, "ABC";
    WriteAnyBin bin, where;
    WriteRawBytes bin, raw \NoOfBytes:=4;
    line := ReadStr(log \Delim:=";" \RemoveCR \DiscardHeaders \Time:=2 \Line:=3);
    IF line = EOF THEN
      value := ReadNum(log \Delim:=" " \Time:=1);
    ENDIF
    value := ReadBin(bin \Time:=1);
    IF value = EOF_BIN name := ReadStrBin(bin, 4 \Time:=1);
    ReadAnyBin bin, where \Time:=1;
    ReadRawBytes bin, raw \Time:=1;
    Rewind log;
    Close log;
    Close bin;
    IF NOT IsFile("HOME:/logs" \Directory) MakeDir "HOME:/logs";
    value := FileSize("HOME:/log.txt");
    CopyFile "HOME:/log.txt", "HOME:/logs/log1.txt";
    RenameFile "HOME:/logs/log1.txt", "HOME:/logs/old.txt";
    OpenDir folder, "HOME:/logs";
    WHILE ReadDir(folder, name) DO
      RemoveFile "HOME:/logs/" + name;
    ENDWHILE
    CloseDir folder;
    RemoveDir "HOME:/logs";
  ERROR
    IF ERRNO = ERR_FILEOPEN OR ERRNO = ERR_FILEACC OR ERRNO = ERR_FILEEOF
        OR ERRNO = ERR_FILEEXIST OR ERRNO = ERR_FILNOTFND THEN
      TRYNEXT;
    ENDIF
  ENDPROC
ENDMODULE

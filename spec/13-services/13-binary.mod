MODULE binary_case
! @format 3
! @section 13
! @expect ok
! @description Open \Bin: WriteBin writes NChar character codes of its buffer, WriteStrBin the bytes of a string; ReadBin reads one byte and EOF_BIN at the end, ReadStrBin a number of characters; without \Read, \Write or \Append a binary file is opened for appending.
! @output size 6
! @output first 72
! @output then i
! @output line feed 10
! @output rest ABC
! @output EOF_BIN
! @output after the end: EOF
! @exit 0
  VAR iodev file;
  VAR num codes{4} := [72, 105, 10, 0];
  VAR num b;
  PROC main()
    Open "RAMDISK:/data.bin", file \Write \Bin;
    WriteBin file, codes, 3;
    WriteStrBin file, "AB";
    Close file;
    Open "RAMDISK:/data.bin", file \Bin;
    WriteStrBin file, "C";
    Close file;
    TPWrite "size " \Num:=FileSize("RAMDISK:/data.bin");
    Open "RAMDISK:/data.bin", file \Read \Bin;
    TPWrite "first " \Num:=ReadBin(file);
    TPWrite "then " + ReadStrBin(file, 1);
    b := ReadBin(file);
    TPWrite "line feed " \Num:=b;
    TPWrite "rest " + ReadStrBin(file, 10);
    b := ReadBin(file);
    IF b = EOF_BIN TPWrite "EOF_BIN";
    TPWrite "after the end: " + ReadStrBin(file, 2);
    Close file;
  ENDPROC
ENDMODULE

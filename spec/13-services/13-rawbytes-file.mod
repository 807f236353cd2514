MODULE rawbytes_file
! @format 3
! @section 13
! @expect ok
! @description WriteRawBytes writes the valid data of a rawbytes (or \NoOfBytes of them) to a file opened with \Bin; ReadRawBytes reads what the file holds into a rawbytes, and raises ERR_RANYBIN_EOF when nothing is left (R-13-raw2).
! @output size 16
! @output read 16
! @output hellohello world
! @output ERR_RANYBIN_EOF
! @exit 0
  VAR iodev file;
  VAR rawbytes raw;
  VAR rawbytes back;
  VAR string s;
  PROC main()
    PackRawBytes "hello world", raw, 1 \ASCII;
    Open "HOME:/raw.bin", file \Write \Bin;
    WriteRawBytes file, raw \NoOfBytes:=5;
    WriteRawBytes file, raw;
    Close file;
    TPWrite "size " \Num:=FileSize("HOME:/raw.bin");
    Open "HOME:/raw.bin", file \Read \Bin;
    ReadRawBytes file, back;
    TPWrite "read " \Num:=RawBytesLen(back);
    UnpackRawBytes back, 1, s \ASCII:=RawBytesLen(back);
    TPWrite s;
    ReadRawBytes file, back;
    TPWrite "not reached";
  ERROR
    IF ERRNO = ERR_RANYBIN_EOF TPWrite "ERR_RANYBIN_EOF";
    Close file;
    RETURN;
  ENDPROC
ENDMODULE

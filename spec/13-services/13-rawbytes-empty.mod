MODULE rawbytes_empty
! @format 3
! @section 13
! @expect ok
! @description Nothing to pack, unpack, copy or read (R-13-raw1 to -raw3): UnpackRawBytes \ASCII:=0 gives "" inside the valid data, right after it and in an empty rawbytes; PackRawBytes "" packs nothing; CopyRawBytes from right after the valid data (an empty rawbytes from 1) copies nothing; ReadRawBytes at the end of a file raises ERR_RANYBIN_EOF, which a handler's TRYNEXT passes over as a motion-program reader does; an index beyond that, a byte to take beyond the data, \ASCII beyond 80 are still errors.
! @output inside []
! @output after []
! @output empty [] 0
! @output packed nothing 2
! @output frame 4
! @output copied after the data 4
! @output chunk 2
! @output ERR_RANYBIN_EOF
! @output end 0
! @output ERR_OUTOFBND
! @output ERR_OUTOFBND
! @output ERR_OUTOFBND
! @output ERR_ARGVALERR
! @output ERR_ARGVALERR
! @exit 0
  VAR rawbytes raw;
  VAR rawbytes empty;
  VAR rawbytes frame;
  VAR rawbytes back;
  VAR iodev file;
  VAR string s := "x";

  ! As a reader of a binary motion program fills its buffer: ClearRawBytes, then ReadRawBytes;
  ! at the end of the file the handler skips the read, and the length 0 says so.
  FUNC num fill()
    ClearRawBytes back;
    ReadRawBytes file, back;
    RETURN RawBytesLen(back);
  ERROR
    IF ERRNO = ERR_RANYBIN_EOF THEN
      TPWrite "ERR_RANYBIN_EOF";
      SkipWarn;
      TRYNEXT;
    ENDIF
  ENDFUNC

  PROC corner(num k)
    TEST k
    CASE 1:
      UnpackRawBytes raw, 4, s \ASCII:=0;
    CASE 2:
      UnpackRawBytes raw, 3, s \ASCII:=1;
    CASE 3:
      CopyRawBytes raw, 3, frame, 5 \NoOfBytes:=1;
    CASE 4:
      UnpackRawBytes raw, 1, s \ASCII:=81;
    DEFAULT:
      UnpackRawBytes raw, 1, s \ASCII:=-1;
    ENDTEST
    TPWrite "not reached";
  ERROR
    IF ERRNO = ERR_OUTOFBND TPWrite "ERR_OUTOFBND";
    IF ERRNO = ERR_ARGVALERR TPWrite "ERR_ARGVALERR";
    RETURN;
  ENDPROC

  PROC main()
    PackRawBytes "AB", raw, 1 \ASCII;
    UnpackRawBytes raw, 2, s \ASCII:=0;
    TPWrite "inside [" + s + "]";
    s := "x";
    UnpackRawBytes raw, 3, s \ASCII:=0;
    TPWrite "after [" + s + "]";
    s := "x";
    UnpackRawBytes empty, 1, s \ASCII:=0;
    TPWrite "empty [" + s + "] " \Num:=RawBytesLen(empty);
    PackRawBytes "", raw, 3 \ASCII;
    TPWrite "packed nothing " \Num:=RawBytesLen(raw);
    ! A length prefix, then a body that is empty: the reply of a driver with nothing to say.
    PackRawBytes 0, frame, 1 \IntX:=DINT;
    CopyRawBytes empty, 1, frame, 5;
    TPWrite "frame " \Num:=RawBytesLen(frame);
    CopyRawBytes raw, 3, frame, 5;
    TPWrite "copied after the data " \Num:=RawBytesLen(frame);
    Open "HOME:/program.bin", file \Write \Bin;
    WriteRawBytes file, raw;
    Close file;
    Open "HOME:/program.bin", file \Read \Bin;
    TPWrite "chunk " \Num:=fill();
    TPWrite "end " \Num:=fill();
    Close file;
    FOR k FROM 1 TO 5 DO
      corner k;
    ENDFOR
  ENDPROC
ENDMODULE

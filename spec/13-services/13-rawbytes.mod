MODULE rawbytes_case
! @format 3
! @section 13
! @expect ok
! @description PackRawBytes packs a value at StartIndex as \IntX integers (little-endian, or big-endian with \Network), \Float4, \Hex1 or \ASCII; UnpackRawBytes reads them back; RawBytesLen is the length of the valid data, ClearRawBytes clears from \FromIndex, CopyRawBytes copies bytes between rawbytes; an index beyond the data raises ERR_OUTOFBND.
! @output empty 0
! @output length 19
! @output little-endian 258
! @output read little-endian 513
! @output network 258
! @output signed -2
! @output unsigned 254
! @output float 1.5
! @output hex 255
! @output ascii RAPID
! @output udint 4294967295
! @output copy RAP!
! @output cleared from 3 2
! @output cleared 0
! @output ERR_OUTOFBND
! @exit 0
  VAR rawbytes raw;
  VAR rawbytes other;
  VAR num n;
  VAR dnum d;
  VAR dnum big := 4294967295;
  VAR string s;
  PROC main()
    TPWrite "empty " \Num:=RawBytesLen(raw);
    PackRawBytes 258, raw, 1 \IntX:=UINT;
    PackRawBytes 258, raw \Network, 3 \IntX:=UINT;
    PackRawBytes -2, raw, 5 \IntX:=SINT;
    PackRawBytes 1.5, raw, 6 \Float4;
    PackRawBytes 255, raw, 10 \Hex1;
    PackRawBytes "RAPID", raw, 11 \ASCII;
    PackRawBytes big, raw, 16 \IntX:=UDINT;
    TPWrite "length " \Num:=RawBytesLen(raw);
    UnpackRawBytes raw, 1, n \IntX:=UINT;
    TPWrite "little-endian " \Num:=n;
    UnpackRawBytes raw, 3, n \IntX:=UINT;
    TPWrite "read little-endian " \Num:=n;
    UnpackRawBytes raw \Network, 3, n \IntX:=UINT;
    TPWrite "network " \Num:=n;
    UnpackRawBytes raw, 5, n \IntX:=SINT;
    TPWrite "signed " \Num:=n;
    UnpackRawBytes raw, 5, n \IntX:=USINT;
    TPWrite "unsigned " \Num:=n;
    UnpackRawBytes raw, 6, n \Float4;
    TPWrite "float " \Num:=n;
    UnpackRawBytes raw, 10, n \Hex1;
    TPWrite "hex " \Num:=n;
    UnpackRawBytes raw, 11, s \ASCII:=5;
    TPWrite "ascii " + s;
    UnpackRawBytes raw, 16, d \IntX:=UDINT;
    TPWrite "udint " \Dnum:=d;
    CopyRawBytes raw, 11, other, 1 \NoOfBytes:=3;
    PackRawBytes "!", other, RawBytesLen(other) + 1 \ASCII;
    UnpackRawBytes other, 1, s \ASCII:=RawBytesLen(other);
    TPWrite "copy " + s;
    ClearRawBytes raw \FromIndex:=3;
    TPWrite "cleared from 3 " \Num:=RawBytesLen(raw);
    ClearRawBytes raw;
    TPWrite "cleared " \Num:=RawBytesLen(raw);
    UnpackRawBytes raw, 1, n \IntX:=UINT;
    TPWrite "not reached";
  ERROR
    IF ERRNO = ERR_OUTOFBND TPWrite "ERR_OUTOFBND";
    RETURN;
  ENDPROC
ENDMODULE

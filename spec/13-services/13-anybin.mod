MODULE anybin_case
! @format 3
! @section 13
! @expect ok
! @description WriteAnyBin writes a value of any value type and ReadAnyBin reads it back into data of the same type; data of another type raise ERR_RANYBIN_CHK, and reading past the last value ERR_RANYBIN_EOF.
! @output bolt 12 TRUE
! @output [1,2,3]
! @output [100,200.5,-300]
! @output ERR_RANYBIN_CHK
! @output text
! @output ERR_RANYBIN_EOF
! @exit 0
  RECORD part
    string name;
    num count;
    bool ok;
  ENDRECORD
  VAR iodev file;
  VAR part p := ["bolt", 12, TRUE];
  VAR part q;
  VAR num arr{3} := [1, 2, 3];
  VAR num brr{3};
  VAR pos target := [100, 200.5, -300];
  VAR pos here;
  PROC main()
    Open "HOME:/any.bin", file \Write \Bin;
    WriteAnyBin file, p;
    WriteAnyBin file, arr;
    WriteAnyBin file, target;
    WriteAnyBin file, "text";
    Close file;
    Open "HOME:/any.bin", file \Read \Bin;
    ReadAnyBin file, q;
    TPWrite q.name + " " + ValToStr(q.count) + " " + ValToStr(q.ok);
    ReadAnyBin file, brr;
    TPWrite ValToStr(brr);
    ReadAnyBin file, here;
    TPWrite "" \Pos:=here;
    TPWrite ReadNumber();
    TPWrite ReadText();
    TPWrite ReadText();
    Close file;
    RemoveFile "HOME:/any.bin";
  ENDPROC

  FUNC string ReadNumber()
    VAR num x;
    ReadAnyBin file, x;
    RETURN ValToStr(x);
  ERROR
    IF ERRNO = ERR_RANYBIN_CHK RETURN "ERR_RANYBIN_CHK";
    IF ERRNO = ERR_RANYBIN_EOF RETURN "ERR_RANYBIN_EOF";
  ENDFUNC

  FUNC string ReadText()
    VAR string t;
    ReadAnyBin file, t;
    RETURN t;
  ERROR
    IF ERRNO = ERR_RANYBIN_CHK RETURN "ERR_RANYBIN_CHK";
    IF ERRNO = ERR_RANYBIN_EOF RETURN "ERR_RANYBIN_EOF";
  ENDFUNC
ENDMODULE

MODULE example_skipwarn
! @section 7.5
! @expect ok
! @description The example of section 7.5 (an empty line before ERROR, an optional argument right after a string).
  PROC routine1()
    VAR iodev report;
    Open "HOME:" \File:= "FILE1.DOC", report;
    Write report, "No parts from Rob1="\Num:=reg1;
    Close report;

  ERROR
    IF ERRNO = ERR_FILEOPEN THEN
      WaitTime 0.1;
      SkipWarn;
      RETRY;
    ENDIF
  ENDPROC
ENDMODULE

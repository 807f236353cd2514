MODULE skipwarn_manual_example
! @format 3
! @section 7.5
! @expect ok
! @home home
! @statement-time 0
! @description Section 7.5's example as printed (reg1 declared here, as the controller's user module would): Open fails with ERR_FILEOPEN (HOME:/FILE1.DOC is a folder, standing for a file another system keeps busy), the handler waits 0.1 s, SkipWarn, RETRY. "最多重试次数取决于参数No Of Retry": with the default 4, the fifth RETRY raises ERR_EXCRTYMAX in the handler, which goes to the system error handler (section 7.1).
! @exit 1
! @error ERR_EXCRTYMAX 24:4
  VAR num reg1 := 1;
  PROC main()
    routine1;
  ENDPROC
PROC routine1()
   VAR iodev report;
   Open "HOME:" \File:= "FILE1.DOC", report;
   Write report, "No parts from Robl="\Num:=reg1;
   Close report;

ERROR
   IF ERRNO = ERR_FILEOPEN THEN
     WaitTime 0.1;
   SkipWarn;
   RETRY;
   ENDIF
ENDPROC
ENDMODULE

MODULE restrictions
! @format 3
! @section 6.1
! @section 6.2
! @expect ok
! @description The statements the debugger session test/golden/debug-back-refused.cmd steps backward over: labels, assignments and CONNECT are no-operations backward; a procedure with an empty BACKWARD handler is a no-operation; one without BACKWARD handler (an installed one too: IDelete), compound statements (a compact IF) and other simple statements (GOTO) refuse, and so does the top of a statement list (sections 6.1, 6.2). Run forward, the program writes its lines.
! @exit 0
! @output quiet
! @output no back
! @output i=1
! @output done
  VAR num i := 0;
  VAR intnum irq;
  PROC Quiet()
    TPWrite "quiet";
  BACKWARD
  ENDPROC
  PROC NoBack()
    TPWrite "no back";
  ENDPROC
  TRAP t
  ENDTRAP
  PROC main()
    Quiet;
    NoBack;
    IF i = 0 i := 1;
    TPWrite "i=" \Num:=i;
    GOTO lab;
    lab:
    CONNECT irq WITH t;
    IDelete irq;
    i := 2;
    TPWrite "done";
  ENDPROC
ENDMODULE

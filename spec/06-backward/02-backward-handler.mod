MODULE backward_handler
! @format 3
! @section 6.2
! @expect ok
! @description A procedure's BACKWARD handler is part of it but does not run forward: a forward call runs the body only (section 6.2). Backward execution of these calls is pinned by the debugger sessions test/golden/debug-backward*.cmd.
! @exit 0
! @output forward 1
! @output forward 2
! @output n=3
  VAR num n := 0;
  PROC Forth(num k)
    n := n + k;
    TPWrite "forward " \Num:=k;
  BACKWARD
    n := n - k;
    TPWrite "backward " \Num:=k;
  ENDPROC
  PROC Quiet()
    TPWrite "quiet";
  BACKWARD
  ENDPROC
  PROC NoBack()
    TPWrite "no back";
  ENDPROC
  PROC main()
    Forth 1;
    n := n + 0;
    Forth 2;
    TPWrite "n=" \Num:=n;
  ENDPROC
ENDMODULE

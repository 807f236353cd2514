MODULE isleep_safe
! @format 3
! @section 8
! @section 11
! @section 12
! @expect ok
! @statement-time 0
! @description ISleep of a safe interrupt (ordered with \SingleSafe) raises ERR_INOISSAFE (chapter 12: "如果尝试暂时停用安全中断,则采用ISleep") and leaves it active; ordered again with \Single it is no longer safe, and ISleep deactivates it, so that its timer's interrupt is discarded (doc/rulings.md R-8-w).
! @output ISleep ERR_INOISSAFE
! @output served 1
! @output served 1
  VAR intnum t;
  VAR num n := 0;
  TRAP tick
    n := n + 1;
  ENDTRAP
  PROC main()
    CONNECT t WITH tick;
    ITimer \SingleSafe, 0.5, t;
    ISleep t;
    WaitTime 1;
    TPWrite "served " \Num:=n;
    ITimer \Single, 0.5, t;
    ISleep t;
    WaitTime 1;
    TPWrite "served " \Num:=n;
  ERROR
    IF ERRNO = ERR_INOISSAFE TPWrite "ISleep ERR_INOISSAFE";
    TRYNEXT;
  ENDPROC
ENDMODULE

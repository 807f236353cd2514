MODULE installed_and_built_in
! @format 2
! @section 4.6
! @section 11
! @expect ok
! @description Calls of the built-in procedures IWatch, ISleep and DebugBreak (chapter 11) and of the installed TPWrite with each alternative.
  VAR intnum ino;
  VAR num n;
  VAR pos p;
  VAR orient o;
  VAR dnum d;
  PROC main()
    IWatch ino;
    ISleep ino;
    DebugBreak;
    TPWrite "Start";
    TPWrite "n = " \Num:=n;
    TPWrite "ok" \Bool:=TRUE;
    TPWrite "p" \Pos:=p;
    TPWrite "o" \Orient:=o;
    TPWrite "d" \Dnum:=d;
  ENDPROC
ENDMODULE

MODULE example_built_in_routines
! @section 11
! @expect ok
! @description Calls of each built-in routine of chapter 11.
  VAR intnum ino;
  VAR num n;
  VAR bool b;
  PROC p(INOUT num d, VAR num arr{*} \switch s)
    n := Dim(arr, 1);
    b := Present(s);
    DebugBreak;
    IWatch ino;
    ISleep ino;
    b := IsPers(d) OR IsVar(d);
  ENDPROC
ENDMODULE

MODULE string_80_bytes
! @format 3
! @section 2.13
! @section 3.12
! @expect ok
! @description A concatenation of exactly 80 bytes is allowed (section 2.13: at most 80 bytes).
! @output len=80
! @exit 0
  PROC main()
    VAR string s40 := "0123456789012345678901234567890123456789";
    VAR string s;
    s := s40 + s40;
    TPWrite "len=" \Num:=StrLen(s);
  ENDPROC
ENDMODULE

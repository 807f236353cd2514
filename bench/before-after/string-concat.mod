MODULE BaStringConcat
  ! String concatenation: a string grown a digit at a time to RAPID's 80 characters, then
  ! started again; NumToStr, StrLen and StrPart on the way (bench/before-after.sh).
  PROC main()
    VAR string s := "";
    VAR string last := "";
    VAR num full := 0;
    VAR dnum chars := 0;
    FOR k FROM 1 TO 200000 DO
      s := s + NumToStr(k MOD 10, 0);
      IF StrLen(s) = 80 THEN
        full := full + 1;
        chars := chars + NumToDnum(StrLen(s));
        last := StrPart(s, 1, 10) + "|" + StrPart(s, 71, 10);
        s := "";
      ENDIF
    ENDFOR
    TPWrite "full=" \Num:=full;
    TPWrite "chars=" \Dnum:=chars;
    TPWrite "last=" + last;
    TPWrite "rest=" + s;
  ENDPROC
ENDMODULE

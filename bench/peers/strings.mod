MODULE bench_strings
  ! 100,000 string concatenations, with StrLen and StrPart keeping the string under 80 characters.
  PROC main()
    VAR string s := "";
    VAR num total := 0;
    FOR k FROM 1 TO 100000 DO
      s := s + "ab";
      IF StrLen(s) > 70 THEN
        s := StrPart(s, 11, StrLen(s) - 10);
      ENDIF
      total := total + StrLen(s);
    ENDFOR
    TPWrite "s=" + s;
    TPWrite "total=" \Num:=total;
  ENDPROC
ENDMODULE

MODULE BaRecordUpdate
  ! Record updates: 100 records of an array, each read whole, three fields changed, written back
  ! whole and one field written in place, 2,000 rounds (bench/before-after.sh).
  RECORD ba_point
    num x;
    num y;
    dnum n;
    string tag;
  ENDRECORD

  VAR ba_point pts{100};

  PROC main()
    VAR ba_point p;
    VAR dnum total := 0;
    FOR r FROM 1 TO 2000 DO
      FOR k FROM 1 TO 100 DO
        p := pts{k};
        p.x := p.x + 1;
        p.y := p.y + k;
        p.n := p.n + 1;
        pts{k} := p;
        pts{k}.tag := "r" + NumToStr(r MOD 10, 0);
      ENDFOR
    ENDFOR
    FOR k FROM 1 TO 100 DO
      total := total + pts{k}.n + NumToDnum(pts{k}.y);
    ENDFOR
    TPWrite "pts{1}=" + ValToStr(pts{1});
    TPWrite "pts{100}=" + ValToStr(pts{100});
    TPWrite "total=" \Dnum:=total;
  ENDPROC
ENDMODULE

MODULE bench_bubble
  ! Bubble sort of 2,000 nums in an array, filled by a linear congruential sequence.
  VAR num a{2000};

  PROC main()
    VAR num x := 1;
    VAR num t;
    VAR num sum := 0;
    FOR k FROM 1 TO 2000 DO
      x := (x * 75 + 74) MOD 65537;
      a{k} := x;
    ENDFOR
    FOR i FROM 2000 TO 2 STEP -1 DO
      FOR j FROM 1 TO i - 1 DO
        IF a{j} > a{j + 1} THEN
          t := a{j};
          a{j} := a{j + 1};
          a{j + 1} := t;
        ENDIF
      ENDFOR
    ENDFOR
    FOR k FROM 1 TO 2000 STEP 100 DO
      sum := (sum + a{k}) MOD 65537;
    ENDFOR
    TPWrite "first=" \Num:=a{1};
    TPWrite "last=" \Num:=a{2000};
    TPWrite "check=" \Num:=sum;
  ENDPROC
ENDMODULE

MODULE BaBubbleSort
  ! Bubble sort of 2,000 nums made by a linear congruential generator: array indexing,
  ! nested loops, comparisons and swaps (bench/before-after.sh).
  CONST num N := 2000;
  VAR num a{N};

  PROC fill()
    VAR num x := 12345;
    FOR k FROM 1 TO N DO
      ! 65537 * 75 + 74 < 2^23: exact in num
      x := (x * 75 + 74) MOD 65537;
      a{k} := x;
    ENDFOR
  ENDPROC

  PROC sort()
    VAR num t;
    VAR bool swapped := TRUE;
    VAR num last := N;
    WHILE swapped DO
      swapped := FALSE;
      FOR k FROM 1 TO last - 1 DO
        IF a{k} > a{k + 1} THEN
          t := a{k};
          a{k} := a{k + 1};
          a{k + 1} := t;
          swapped := TRUE;
        ENDIF
      ENDFOR
      last := last - 1;
    ENDWHILE
  ENDPROC

  PROC main()
    VAR dnum sum := 0;
    VAR bool sorted := TRUE;
    fill;
    sort;
    FOR k FROM 1 TO N DO
      sum := sum + NumToDnum(a{k});
      IF k > 1 THEN
        IF a{k - 1} > a{k} sorted := FALSE;
      ENDIF
    ENDFOR
    TPWrite "sorted=" \Bool:=sorted;
    TPWrite "first=" \Num:=a{1};
    TPWrite "last=" \Num:=a{N};
    TPWrite "sum=" \Dnum:=sum;
  ENDPROC
ENDMODULE

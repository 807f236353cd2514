MODULE BaDnumLoop
  ! A loop of 1,000,000 rounds on dnum data: 500000500000 is beyond num's exact integers
  ! (bench/before-after.sh).
  PROC main()
    VAR dnum i := 0;
    VAR dnum s := 0;
    WHILE i < 1000000 DO
      i := i + 1;
      s := s + i;
    ENDWHILE
    TPWrite "i=" \Dnum:=i;
    TPWrite "s=" \Dnum:=s;
  ENDPROC
ENDMODULE

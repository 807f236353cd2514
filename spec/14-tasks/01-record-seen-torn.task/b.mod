MODULE torn_b
! @task T_B
  PERS pos p;
  PROC main()
    VAR pos q;
    q := p;
    TPWrite "B read " \Pos := q;
  ENDPROC
ENDMODULE

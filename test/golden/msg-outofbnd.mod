MODULE msg_outofbnd
  VAR num a{3} := [1, 2, 3];
  VAR num k := 4;
  PROC main()
    TPWrite "a{k} = " \Num:=a{k};
  ENDPROC
ENDMODULE

MODULE errm
  VAR num a{3};
  PROC f(num i)
    a{i} := 1;
  ENDPROC
  PROC main()
    TPWrite "start";
    f 4;
  ENDPROC
ENDMODULE

MODULE Places
  VAR num m{2,3};
  VAR pose frame;
  VAR string names{2} := ["a", "b"];
  PROC set(INOUT num x, num v)
    x := v;
  ENDPROC
  PROC main()
    VAR num k := 2;
    m{k, k + 1} := 1.5;
    frame.trans.z := -0.1;
    frame.rot := [1, 0, 0, 0];
    set m{1, 1}, 1E+20;
    names{k} := "say ""hi""";
    TPWrite names{2};
  ENDPROC
ENDMODULE

MODULE debug_expressions
  RECORD station
    string name;
    pos offset;
    num count;
  ENDRECORD
  CONST num limit := 4;
  VAR station st := ["weld", [10, 20, 30], 7];
  VAR station line{2};
  VAR num grid{2, 3} := [[1, 2, 3], [4, 5, 6]];
  VAR dnum big := 5000000000;
  PERS pos home := [100, 0, 50];
  PROC main()
    VAR num k := 2;
    VAR bool ready;
    k := k + 1;
    TPWrite "k " \Num:=k;
    TPWrite "count " \Num:=st.count;
    TPWrite "x " \Num:=home.x;
  ENDPROC
ENDMODULE

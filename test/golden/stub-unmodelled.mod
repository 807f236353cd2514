MODULE client
  VAR num answer := 7;
  VAR string kind := "none";
  VAR num status := 7;
  PROC main()
    TPReadFK answer, "Continue?", "Yes", "No", "", "", "";
    TPReadFK answer, "Continue?", "Yes", "No", "", "", "";
    TPWrite "answer: " \Num:=answer;
    status := RunMode();
    TPWrite "status: " \Num:=status;
    IF IsSysId("6400-1234") THEN
      TPWrite "that system";
    ELSE
      TPWrite "another system";
    ENDIF
    kind := Type(answer);
    TPWrite "kind: """ + kind + """";
    TPWrite "done";
  ENDPROC
ENDMODULE

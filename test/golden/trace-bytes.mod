MODULE trace_bytes
  ! A value of bytes that are not UTF-8 (character codes above \7F) in the JSON trace.
  VAR string s;
  PROC main()
    s := "e\E5\80\FF";
  ENDPROC
ENDMODULE

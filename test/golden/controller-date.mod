MODULE date
  PROC main()
    TPWrite CDate() + " " + CTime();
    TPWrite "weekday " \Num:=GetTime(\WDay);
    WaitTime 43200;
    TPWrite CDate() + " " + CTime();
    TPWrite "weekday " \Num:=GetTime(\WDay);
  ENDPROC
ENDMODULE

MODULE predefined_taskid_b
! @task T_LOG
  PERS bool moved;
  PROC main()
    VAR jointtarget j;
    WaitUntil moved;
    j := CJointT(\TaskRef:=T_ROB1Id);
    TPWrite "log: axis 1 of T_ROB1 " + NumToStr(j.robax.rax_1, 0);
    j := CJointT(\TaskRef:=T_LOGId);
    TPWrite "log: my own " + NumToStr(j.robax.rax_1, 0);
  ENDPROC
ENDMODULE

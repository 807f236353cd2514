MODULE rmq_left_b
! @task T_B
  VAR rmqmessage request;
  VAR rmqslot asker;
  VAR string late := "late";
  PROC main()
    RMQReadWait request;
    RMQGetMsgHeader request \SenderId:=asker;
    WaitTime 1;
    RMQSendMessage asker, late;
  ENDPROC
ENDMODULE

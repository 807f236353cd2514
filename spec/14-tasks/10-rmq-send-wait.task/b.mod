MODULE rmq_wait_b
! @task T_B
  VAR rmqmessage request;
  VAR rmqheader head;
  VAR rmqslot asker;
  VAR num n;
  VAR string reply;
  PROC main()
    RMQReadWait request \TimeOut:=WAIT_MAX;
    RMQGetMsgHeader request \Header:=head \SenderId:=asker;
    TPWrite "B read " + head.datatype + " from " + RMQGetSlotName(asker);
    RMQGetMsgData request, n;
    WaitTime 0.5;
    reply := "twice " + NumToStr(n, 0) + " is " + NumToStr(2 * n, 0);
    RMQSendMessage asker, reply;
  ENDPROC
ENDMODULE

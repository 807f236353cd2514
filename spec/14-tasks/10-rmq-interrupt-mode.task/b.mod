MODULE rmq_mode_b
! @task T_B
  VAR intnum on_num;
  VAR num n;
  VAR rmqmessage msg;
  TRAP got_num
    VAR rmqmessage m;
    RMQGetMessage m;
    RMQGetMsgData m, n;
    TPWrite "B trap: " + NumToStr(n, 0);
  ENDTRAP
  PROC main()
    CONNECT on_num WITH got_num;
    IRMQMessage n, on_num;
    RMQReadWait msg \TimeOut:=0;
    WaitTime 2;
    RMQGetMessage msg;
    TPWrite "not reached";
  ERROR
    IF ERRNO = ERR_RMQ_INVALID TPWrite "B: RMQReadWait in interrupt mode: ERR_RMQ_INVALID";
    IF ERRNO = ERR_RMQ_NOMSG THEN
      TPWrite "B: the string was discarded: ERR_RMQ_NOMSG";
      RETURN;
    ENDIF
    TRYNEXT;
  ENDPROC
ENDMODULE

MODULE rmq_timeout_b
! @task T_B
  VAR rmqmessage request;
  VAR rmqslot asker;
  VAR num wrong := 0;
  VAR clock watch;
  PROC main()
    ClkStart watch;
    RMQReadWait request \TimeOut:=0.3;
    TPWrite "not reached";
  ERROR
    IF ERRNO = ERR_RMQ_TIMEOUT THEN
      TPWrite "B timed out after " + NumToStr(ClkRead(watch), 1) + " s";
      answer_wrongly;
      RETURN;
    ENDIF
  ENDPROC
  PROC answer_wrongly()
    RMQReadWait request;
    RMQGetMsgHeader request \SenderId:=asker;
    ! A num, where T_ROB1 waits for a string.
    RMQSendMessage asker, wrong;
    RMQReadWait request \TimeOut:=0;
  ERROR
    IF ERRNO = ERR_RMQ_TIMEOUT TPWrite "B: no message, no wait";
    RETURN;
  ENDPROC
ENDMODULE

MODULE rmq_full_b
! @task T_B
  VAR rmqmessage msg;
  VAR rmqheader head;
  VAR num k;
  VAR num count := 0;
  PROC main()
    WaitTime 1;
    WHILE TRUE DO
      RMQReadWait msg \TimeOut:=0;
      count := count + 1;
      RMQGetMsgHeader msg \Header:=head;
      IF head.ndim = 0 THEN
        RMQGetMsgData msg, k;
        TPWrite "B: " + NumToStr(k, 0);
      ELSE
        TPWrite "B: num{" + NumToStr(head.dim1, 0) + "}";
      ENDIF
    ENDWHILE
  ERROR
    IF ERRNO = ERR_RMQ_TIMEOUT TPWrite "B: " + NumToStr(count, 0) + " messages";
    RETURN;
  ENDPROC
ENDMODULE

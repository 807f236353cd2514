MODULE rmq_timeout_a
! @format 4
! @task T_ROB1
! @section 14
! @section 7
! @expect ok
! @description ABB's RMQSendWait \TimeOut and RMQReadWait \TimeOut (RAPID Message Queue): no message comes within the time-out, ERR_RMQ_TIMEOUT is raised and handled; an answer of another data type than ReceiveDataType's does not end RMQSendWait and waits in the queue; \TimeOut:=0 does not wait at all (doc/rulings.md R-14-rmq2, R-14-rmq5).
! @statement-time 0
! @output B timed out after 0.3 s
! @output B: no message, no wait
! @output A timed out after 1.0 s
! @output A then read num
  VAR rmqslot to_b;
  VAR rmqmessage answer;
  VAR rmqheader head;
  VAR num question := 1;
  VAR string text;
  VAR clock watch;
  PROC main()
    RMQFindSlot to_b, "RMQ_T_B";
    WaitTime 0.5;
    ClkStart watch;
    RMQSendWait to_b, question, answer, text \TimeOut:=1;
    TPWrite "not reached";
  ERROR
    IF ERRNO = ERR_RMQ_TIMEOUT THEN
      TPWrite "A timed out after " + NumToStr(ClkRead(watch), 1) + " s";
      RMQReadWait answer \TimeOut:=0;
      RMQGetMsgHeader answer \Header:=head;
      TPWrite "A then read " + head.datatype;
      RETURN;
    ENDIF
  ENDPROC
ENDMODULE

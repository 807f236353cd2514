MODULE rmq_one_task
! @format 3
! @section 14
! @expect ok
! @description ABB's RMQSendMessage, RMQEmptyQueue and RMQReadWait (RAPID Message Queue) in one task: it sends to its own slot RMQ_T_ROB1; RMQEmptyQueue empties its queue; RMQReadWait \TimeOut:=WAIT_MAX with no message to come, and no other task, never ends: a deadlock (doc/rulings.md R-14-rmq2, R-14-rmq5).
! @output RMQ_T_ROB1 read 3
! @exit 3
  VAR rmqslot me;
  VAR rmqmessage msg;
  VAR num k;
  PROC main()
    RMQFindSlot me, "RMQ_T_ROB1";
    FOR i FROM 1 TO 3 DO
      k := i;
      RMQSendMessage me, k;
      IF i = 2 RMQEmptyQueue;
    ENDFOR
    RMQReadWait msg;
    RMQGetMsgData msg, k;
    TPWrite RMQGetSlotName(me) + " read " + NumToStr(k, 0);
    RMQReadWait msg \TimeOut:=WAIT_MAX;
    TPWrite "not reached";
  ENDPROC
ENDMODULE

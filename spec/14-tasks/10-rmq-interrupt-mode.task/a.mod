MODULE rmq_mode_a
! @format 4
! @task T_ROB1
! @section 14
! @section 8
! @expect ok
! @description ABB's IRMQMessage, RMQGetMessage and RMQReadWait (RAPID Message Queue): a task that ordered an interrupt with IRMQMessage is in interrupt mode: a message of a data type with no interrupt ordered is discarded, RMQReadWait is refused (ERR_RMQ_INVALID, where ABB stops the task), and RMQGetMessage of an empty queue is ERR_RMQ_NOMSG (doc/rulings.md R-14-rmq2).
! @output B: RMQReadWait in interrupt mode: ERR_RMQ_INVALID
! @output A sent a string and a num
! @output B trap: 7
! @output B: the string was discarded: ERR_RMQ_NOMSG
  VAR rmqslot to_b;
  VAR string s := "no interrupt for strings";
  VAR num k := 7;
  PROC main()
    WaitTime 0.5;
    RMQFindSlot to_b, "RMQ_T_B";
    RMQSendMessage to_b, s;
    RMQSendMessage to_b, k;
    TPWrite "A sent a string and a num";
  ENDPROC
ENDMODULE

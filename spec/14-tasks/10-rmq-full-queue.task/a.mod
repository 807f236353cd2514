MODULE rmq_full_a
! @format 4
! @task T_ROB1
! @section 14
! @section 7
! @expect ok
! @description ABB's RMQFindSlot and RMQSendMessage (RAPID Message Queue): a slot name is RMQ_ and the task's name, another is ERR_RMQ_NAME; data longer than RMQ Max Message Size (400 bytes by default, as ValToStr writes it) is ERR_RMQ_MSGSIZE; a queue holding RMQ Max No Of Messages (5 by default) is ERR_RMQ_FULL for the sender (doc/rulings.md R-14-rmq1, R-14-rmq2).
! @output A: T_B is no slot name: ERR_RMQ_NAME
! @output A: 401 bytes: ERR_RMQ_MSGSIZE
! @output A: message 6: ERR_RMQ_FULL
! @output B: 1
! @output B: 2
! @output B: 3
! @output B: 4
! @output B: num{199}
! @output B: 5 messages
  VAR rmqslot to_b;
  VAR num k;
  VAR num n{199};
  VAR num big{200};
  PROC main()
    RMQFindSlot to_b, "T_B";
    RMQFindSlot to_b, "rmq_t_b";
    RMQSendMessage to_b, big;
    FOR i FROM 1 TO 4 DO
      k := i;
      RMQSendMessage to_b, k;
    ENDFOR
    RMQSendMessage to_b, n;
    RMQSendMessage to_b, k;
  ERROR
    IF ERRNO = ERR_RMQ_NAME TPWrite "A: T_B is no slot name: ERR_RMQ_NAME";
    IF ERRNO = ERR_RMQ_MSGSIZE TPWrite "A: 401 bytes: ERR_RMQ_MSGSIZE";
    IF ERRNO = ERR_RMQ_FULL TPWrite "A: message 6: ERR_RMQ_FULL";
    TRYNEXT;
  ENDPROC
ENDMODULE

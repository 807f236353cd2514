MODULE rmq_type_a
! @format 4
! @task T_ROB1
! @section 14
! @section 7
! @expect ok
! @description ABB's RMQGetMsgData and RMQGetMsgHeader (RAPID Message Queue): the data of a message goes only into a variable of its type: another type is ERR_RMQ_VALUE, the same type with other dimensions ERR_RMQ_DIM, and an rmqmessage that holds no message ERR_RMQ_INVMSG (doc/rulings.md R-14-rmq4).
! @output B: pos into a num: ERR_RMQ_VALUE
! @output B: pos [1,2,3]
! @output B: num ndim 1 dim1 3
! @output B: num{3} into a num{2}: ERR_RMQ_DIM
! @output B: num{3} [4,5,6]
! @output B: no message: ERR_RMQ_INVMSG
  VAR rmqslot to_b;
  VAR pos where := [1, 2, 3];
  VAR num row{3} := [4, 5, 6];
  PROC main()
    RMQFindSlot to_b, "RMQ_T_B";
    RMQSendMessage to_b, where;
    RMQSendMessage to_b, row;
  ENDPROC
ENDMODULE

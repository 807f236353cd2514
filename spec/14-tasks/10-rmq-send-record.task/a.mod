MODULE rmq_record_a
! @format 4
! @task T_ROB1
! @section 14
! @section 8
! @expect ok
! @description ABB's RMQFindSlot, RMQSendMessage, IRMQMessage, RMQGetMessage, RMQGetMsgHeader, RMQGetMsgData and RMQGetSlotName (RAPID Message Queue): T_B orders an interrupt for messages of its record type part, T_ROB1 sends one with \UserDef, and T_B's trap reads the header and the data (doc/rulings.md R-14-rmq1, R-14-rmq2, R-14-rmq4).
! @output sent to RMQ_T_B
! @output B got part from RMQ_T_ROB1 user 7 ndim 0
! @output B part 12 weld
  RECORD part
    num id;
    string name;
  ENDRECORD
  VAR rmqslot to_b;
  VAR part p := [12, "weld"];
  PROC main()
    WaitTime 0.1;
    RMQFindSlot to_b, "RMQ_T_B";
    RMQSendMessage to_b, p \UserDef:=7;
    p.id := 13;
    TPWrite "sent to " + RMQGetSlotName(to_b);
  ENDPROC
ENDMODULE

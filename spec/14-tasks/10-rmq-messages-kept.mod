MODULE rmq_messages_kept
! @format 3
! @section 14
! @section 7
! @expect ok
! @description ABB's rmqmessage and RMQGetMsgHeader (RAPID Message Queue): an rmqmessage variable that takes message after message holds the last; the controller keeps the last 1000 messages variables took, so that the first of 1001 variables holds none any more: ERR_RMQ_INVMSG (doc/rulings.md R-14-rmq3).
! @output reused: 1001
! @output ms{2}: 2
! @output ms{1}: ERR_RMQ_INVMSG
  VAR rmqslot me;
  VAR rmqmessage one;
  VAR rmqmessage ms{1001};
  VAR rmqheader head;
  VAR num k;
  PROC main()
    RMQFindSlot me, "RMQ_T_ROB1";
    FOR i FROM 1 TO 1001 DO
      k := i;
      RMQSendMessage me, k;
      RMQReadWait one;
    ENDFOR
    RMQGetMsgData one, k;
    TPWrite "reused: " + NumToStr(k, 0);
    FOR i FROM 1 TO 1001 DO
      k := i;
      RMQSendMessage me, k;
      RMQReadWait ms{i};
    ENDFOR
    RMQGetMsgData ms{2}, k;
    TPWrite "ms{2}: " + NumToStr(k, 0);
    RMQGetMsgHeader ms{1} \Header:=head;
    TPWrite "not reached";
  ERROR
    IF ERRNO = ERR_RMQ_INVMSG TPWrite "ms{1}: ERR_RMQ_INVMSG";
    RETURN;
  ENDPROC
ENDMODULE

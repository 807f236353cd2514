MODULE rmq_record_b
! @task T_B
  RECORD part
    num id;
    string name;
  ENDRECORD
  VAR intnum got;
  VAR part p;
  VAR bool done := FALSE;
  TRAP receive
    VAR rmqmessage msg;
    VAR rmqheader head;
    VAR rmqslot sender;
    VAR num user;
    RMQGetMessage msg;
    RMQGetMsgHeader msg \Header:=head \SenderId:=sender \UserDef:=user;
    TPWrite "B got " + head.datatype + " from " + RMQGetSlotName(sender) + " user " + NumToStr(user, 0)
      + " ndim " + NumToStr(head.ndim, 0);
    RMQGetMsgData msg, p;
    TPWrite "B part " + NumToStr(p.id, 0) + " " + p.name;
    done := TRUE;
  ENDTRAP
  PROC main()
    CONNECT got WITH receive;
    IRMQMessage p, got;
    WaitUntil done;
  ENDPROC
ENDMODULE

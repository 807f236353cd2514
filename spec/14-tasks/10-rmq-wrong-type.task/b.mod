MODULE rmq_type_b
! @task T_B
  VAR rmqmessage msg;
  VAR rmqmessage never;
  VAR rmqheader head;
  VAR num n;
  VAR pos p;
  VAR num two{2};
  VAR num three{3};
  PROC main()
    RMQReadWait msg;
    RMQGetMsgData msg, n;
    RMQGetMsgData msg, p;
    TPWrite "B: pos " + ValToStr(p);
    RMQReadWait msg;
    RMQGetMsgHeader msg \Header:=head;
    TPWrite "B: " + head.datatype + " ndim " + NumToStr(head.ndim, 0) + " dim1 " + NumToStr(head.dim1, 0);
    RMQGetMsgData msg, two;
    RMQGetMsgData msg, three;
    TPWrite "B: num{3} " + ValToStr(three);
    RMQGetMsgData never, n;
  ERROR
    IF ERRNO = ERR_RMQ_VALUE TPWrite "B: pos into a num: ERR_RMQ_VALUE";
    IF ERRNO = ERR_RMQ_DIM TPWrite "B: num{3} into a num{2}: ERR_RMQ_DIM";
    IF ERRNO = ERR_RMQ_INVMSG TPWrite "B: no message: ERR_RMQ_INVMSG";
    TRYNEXT;
  ENDPROC
ENDMODULE

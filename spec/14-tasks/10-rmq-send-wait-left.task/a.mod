MODULE rmq_left_a
! @format 4
! @task T_ROB1
! @section 14
! @section 7.2
! @expect ok
! @description ABB's RMQSendWait left by a long jump (§7.2) from a trap: the task awaits no answer any more, so a message of the awaited type that comes later goes to its queue, where RMQReadWait reads it (doc/rulings.md R-14-rmq5).
! @statement-time 0
! @output left the wait at 0.5 s
! @output read the late string 'late' at 1.0 s
  VAR intnum t;
  VAR rmqslot to_b;
  VAR rmqmessage msg;
  VAR num question := 1;
  VAR string text;
  VAR clock watch;
  TRAP failing
    RAISE 33;
  ENDTRAP
  PROC main()
    RMQFindSlot to_b, "RMQ_T_B";
    ClkStart watch;
    CONNECT t WITH failing;
    ITimer \Single, 0.5, t;
    RMQSendWait to_b, question, msg, text \TimeOut:=5;
    TPWrite "not reached";
  ERROR (33)
    TPWrite "left the wait at " + NumToStr(ClkRead(watch), 1) + " s";
    RMQReadWait msg \TimeOut:=2;
    RMQGetMsgData msg, text;
    TPWrite "read the late string '" + text + "' at " + NumToStr(ClkRead(watch), 1) + " s";
    RETURN;
  ENDPROC
ENDMODULE

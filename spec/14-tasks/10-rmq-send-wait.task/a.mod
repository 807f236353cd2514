MODULE rmq_wait_a
! @format 4
! @task T_ROB1
! @section 14
! @expect ok
! @description ABB's RMQSendWait and RMQReadWait (RAPID Message Queue): T_ROB1 sends a num and waits for an answer of type string; T_B, in synchronous mode, reads the request with RMQReadWait, finds its sender with RMQGetMsgHeader \SenderId and answers with RMQSendMessage (doc/rulings.md R-14-rmq2, R-14-rmq5).
! @statement-time 0
! @output B read num from RMQ_T_ROB1
! @output answer 'twice 21 is 42' at 0.5 s
  VAR rmqslot to_b;
  VAR rmqmessage answer;
  VAR num question := 21;
  VAR string text;
  VAR clock watch;
  PROC main()
    RMQFindSlot to_b, "RMQ_T_B";
    ClkStart watch;
    RMQSendWait to_b, question, answer, text \TimeOut:=5;
    RMQGetMsgData answer, text;
    TPWrite "answer '" + text + "' at " + NumToStr(ClkRead(watch), 1) + " s";
  ENDPROC
ENDMODULE

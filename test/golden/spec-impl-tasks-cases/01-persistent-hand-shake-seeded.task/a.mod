MODULE hand_shake_a
! @format 4
! @task T_ROB1
! @section 14
! @schedule 12345
! @expect ok
! @description With a pseudo-random order of turns (@schedule), two tasks hand a system-global persistent back and forth (ch. 14: its current value is shared by every task declaring it with the same name and type); WaitUntil waits for the other task's write.
! @output A sets 1
! @output B saw 1
! @output A saw 2
! @output B saw 3
  PERS num state := 0;
  PROC main()
    TPWrite "A sets 1";
    state := 1;
    WaitUntil state = 2;
    TPWrite "A saw 2";
    state := 3;
  ENDPROC
ENDMODULE

MODULE sync_a
! @format 4
! @task T_ROB1
! @section 14
! @expect ok
! @description WaitSyncTask: each task waits at the synchronisation point (its syncident object's name, R-14-f) until every task of the list has reached it; then all go on. Twice, so that the second meeting counts anew; the task that arrives last goes on first, in the turn it arrives in.
! @output B arrives
! @output A arrives
! @output A goes
! @output B goes
! @output B again
! @output A again
  VAR syncident meet;
  PERS tasks both{2} := [["T_ROB1"], ["T_B"]];
  PROC main()
    WaitTime 1;
    TPWrite "A arrives";
    WaitSyncTask meet, both;
    TPWrite "A goes";
    WaitSyncTask meet, both;
    TPWrite "A again";
  ENDPROC
ENDMODULE

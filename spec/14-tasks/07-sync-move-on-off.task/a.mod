MODULE syncmove_a
! @format 4
! @task T_ROB1
! @section 14
! @expect ok
! @description SyncMoveOn and SyncMoveOff are synchronisation points over the tasks of the list, as WaitSyncTask is (R-14-m): A reaches SyncMoveOn at once but goes on only when B, which waits 2 s first, arrives; between the two, IsSyncMoveOn is TRUE in both tasks, before and after FALSE. The motion task reaches each point only once its robot stands still, so the move with a zone is done before SyncMoveOn lets A go on. At SyncMoveOff B arrives first and waits; A, arriving last, goes on in its own turn, B in the next.
! @output A before FALSE
! @output B before FALSE
! @output B on TRUE
! @output A on TRUE
! @output A waited 2
! @output A in position TRUE
! @output A off FALSE
! @output B off FALSE
  VAR syncident sync_on;
  VAR syncident sync_off;
  PERS tasks all_tasks{2} := [["T_ROB1"], ["T_B"]];
  CONST jointtarget there := [[10, 0, 0, 0, 30, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  PROC main()
    VAR jointtarget j;
    VAR clock c;
    TPWrite "A before " \Bool := IsSyncMoveOn();
    ClkStart c;
    MoveAbsJ there, v100, z50, tool0;
    SyncMoveOn sync_on, all_tasks;
    TPWrite "A on " \Bool := IsSyncMoveOn();
    TPWrite "A waited " \Num := Round(ClkRead(c));
    j := CJointT();
    TPWrite "A in position " \Bool := Abs(j.robax.rax_1 - 10) < 0.01;
    SyncMoveOff sync_off;
    TPWrite "A off " \Bool := IsSyncMoveOn();
  ENDPROC
ENDMODULE

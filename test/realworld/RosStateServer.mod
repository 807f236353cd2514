MODULE RosStateServer
    ! ROS interface, state server. Runs in the semistatic task ROS_STATE.
    ! Sends the joint position of ROB_1 to the connected client about 25 times a second.
    ! A dropped connection is not an error: the server goes back to listening.

    LOCAL CONST num UPDATE_PERIOD := 0.04;
    ! Every n-th message is also written to the trace.
    LOCAL CONST num TRACE_EVERY := 250;

    LOCAL VAR socketdev server_socket;
    LOCAL VAR socketdev client_socket;
    LOCAL VAR rawbytes message;
    LOCAL VAR num seq_counter := 0;
    LOCAL VAR num reconnects := 0;
    LOCAL VAR clock send_clock;

    PROC main()
        TPWrite "ROS state server starting";
        seq_counter := 0;
        ClkReset send_clock;
        RosServerOpen server_socket, client_socket, ROS_STATE_PORT;
        ClkStart send_clock;
        WHILE TRUE DO
            SendJointState;
            WaitUntilNextPeriod;
        ENDWHILE
    ERROR (ROS_ERR_LINK, ERR_SOCK_CLOSED)
        ! Reached from any depth when the client is gone: listen again.
        Incr reconnects;
        ErrWrite \I, "ROS state server", "Client disconnected"
            \RL2:="reconnect " + NumToStr(reconnects, 0);
        RosServerClose server_socket, client_socket;
        WaitTime 1;
        RETRY;
    UNDO
        RosServerClose server_socket, client_socket;
    ENDPROC

    LOCAL PROC SendJointState()
        VAR jointtarget position;

        position := CJointT(\TaskName:="T_ROB1");
        RosBuildJointState message, seq_counter, position;
        RosSendMsg client_socket, message;
        Incr seq_counter;
        IF seq_counter MOD TRACE_EVERY = 0 THEN
            RosTrace "state messages sent" \Value:=seq_counter;
        ENDIF
    ENDPROC

    ! Sleeps for what is left of the update period.
    LOCAL PROC WaitUntilNextPeriod()
        VAR num elapsed;

        elapsed := ClkRead(send_clock);
        ClkReset send_clock;
        ClkStart send_clock;
        IF elapsed < UPDATE_PERIOD THEN
            WaitTime UPDATE_PERIOD - elapsed;
        ELSE
            ! The message took longer than a period: yield once.
            WaitTime 0.001;
        ENDIF
    ENDPROC
ENDMODULE

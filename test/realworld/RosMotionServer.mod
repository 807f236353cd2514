MODULE RosMotionServer
    ! ROS interface, motion server. Runs in the semistatic task ROS_MOTION.
    ! Receives joint trajectory points. A point with sequence number ROS_SEQ_START_DL
    ! starts a download, ROS_SEQ_END_DL ends it and hands the whole trajectory to the
    ! motion task; ROS_SEQ_STOP stops the robot at once. Any other point is streamed:
    ! it is appended to the shared buffer as soon as it arrives. Every request is
    ! answered with a reply carrying SUCCESS or FAILURE.

    LOCAL VAR socketdev server_socket;
    LOCAL VAR socketdev client_socket;
    LOCAL VAR rawbytes request;
    LOCAL VAR rawbytes reply;
    LOCAL VAR RosMsgHeader header;
    LOCAL VAR RosTrajPoint point;

    ! A downloaded trajectory is collected here and copied to the buffer in one go.
    LOCAL VAR RosTrajPoint download{ROS_MAX_POINTS};
    LOCAL VAR num download_size := 0;
    LOCAL VAR bool downloading := FALSE;

    ! Statistics, shown on the FlexPendant when the client disconnects.
    LOCAL VAR num points_received := 0;
    LOCAL VAR num points_rejected := 0;

    PROC main()
        VAR num reply_code;

        TPWrite "ROS motion server starting";
        RosServerOpen server_socket, client_socket, ROS_MOTION_PORT;
        WHILE TRUE DO
            RosReceiveMsg client_socket, request;
            RosUnpackHeader request, header;
            reply_code := HandleRequest();
            IF header.comm_type = ROS_COM_REQUEST THEN
                RosBuildReply reply, header, reply_code;
                RosSendMsg client_socket, reply;
            ENDIF
        ENDWHILE
    ERROR
        IF ERRNO = ROS_ERR_LINK OR ERRNO = ERR_SOCK_CLOSED THEN
            TPWrite "ROS motion client gone, points: " \Num:=points_received;
            IF points_rejected > 0 TPWrite "  rejected: " \Num:=points_rejected;
            downloading := FALSE;
            download_size := 0;
            RosServerOpen server_socket, client_socket, ROS_MOTION_PORT;
            RETRY;
        ENDIF
        RAISE;
    UNDO
        RosServerClose server_socket, client_socket;
    ENDPROC

    ! Handles one message; returns the reply code.
    LOCAL FUNC num HandleRequest()
        IF RawBytesLen(request) < RosBodyLength(header.msg_type) THEN
            ErrWrite \W, "ROS motion server", "Message too short"
                \RL2:=RosHeaderText(header);
            RETURN ROS_REPLY_FAILURE;
        ENDIF
        TEST header.msg_type
        CASE ROS_MSG_PING:
            RETURN ROS_REPLY_SUCCESS;
        CASE ROS_MSG_JOINT_TRAJ_PT:
            RosReadTrajPoint request, point;
            Incr points_received;
            RETURN HandlePoint();
        DEFAULT:
            ErrWrite \W, "ROS motion server", "Unknown message type"
                \RL2:=RosHeaderText(header);
            RETURN ROS_REPLY_FAILURE;
        ENDTEST
    ENDFUNC

    LOCAL FUNC num HandlePoint()
        TEST point.seq
        CASE ROS_SEQ_STOP:
            ros_stop_request := TRUE;
            downloading := FALSE;
            download_size := 0;
            RosLockBuffer;
            RosClearBuffer;
            RosUnlockBuffer;
            RosTrace "stop requested";
            RETURN ROS_REPLY_SUCCESS;
        CASE ROS_SEQ_START_DL:
            downloading := TRUE;
            download_size := 0;
            RETURN ROS_REPLY_SUCCESS;
        CASE ROS_SEQ_END_DL:
            IF NOT downloading RETURN ROS_REPLY_FAILURE;
            downloading := FALSE;
            PublishDownload;
            RETURN ROS_REPLY_SUCCESS;
        DEFAULT:
            IF downloading THEN
                IF download_size >= ROS_MAX_POINTS THEN
                    Incr points_rejected;
                    RETURN ROS_REPLY_FAILURE;
                ENDIF
                Incr download_size;
                download{download_size} := point;
                RETURN ROS_REPLY_SUCCESS;
            ENDIF
            ! Streaming mode.
            IF RosAppendPoint(point) THEN
                RosLockBuffer;
                ros_buffer_new := TRUE;
                RosUnlockBuffer;
                RETURN ROS_REPLY_SUCCESS;
            ENDIF
            Incr points_rejected;
            RETURN ROS_REPLY_FAILURE;
        ENDTEST
    ENDFUNC

    ! Replaces the shared buffer with the downloaded trajectory.
    LOCAL PROC PublishDownload()
        RosLockBuffer;
        FOR i FROM 1 TO download_size DO
            ros_buffer{i} := download{i};
        ENDFOR
        ros_buffer_size := download_size;
        ros_buffer_new := download_size > 0;
        ros_stop_request := FALSE;
        RosUnlockBuffer;
        RosTrace "trajectory published, points" \Value:=download_size;
        download_size := 0;
    ENDPROC
ENDMODULE

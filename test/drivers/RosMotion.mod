MODULE RosMotion
    ! The motion server of a ROS-Industrial robot driver: our own version, written from the
    ! published simple_message format (the simple_message package's reference pages on
    ! docs.ros.org: SimpleMessage, StandardMsgTypes, CommTypes, ReplyTypes, JointTrajPt).
    ! A message is little-endian: int32 length (of what follows), int32 msg_type, int32
    ! comm_type, int32 reply_code, then the body. JOINT_TRAJ_PT (msg_type 11), 64 bytes after the
    ! length: int32 sequence, float32 joint_data[10] (radians), float32 velocity, float32
    ! duration. comm_type 1 = TOPIC, 2 = SERVICE_REQUEST, 3 = SERVICE_REPLY; reply_code 0 =
    ! INVALID (unused), 1 = SUCCESS, 2 = FAILURE. Sequence -4 = STOP_TRAJECTORY.
    ! Each point is moved to with MoveAbsJ, a stop point; a request is answered (SERVICE_REPLY,
    ! SUCCESS, the point echoed) once the robot is there. The client going away stops the
    ! server, and the state server too (ros_stop, shared by the tasks).
    ! The ports are read from HOME:/ros_ports.cfg: the motion port, then the state port.
    PERS bool ros_stop := FALSE;
    LOCAL CONST num MSG_JOINT_TRAJ_PT := 11;
    LOCAL CONST num COMM_SERVICE_REQUEST := 2;
    LOCAL CONST num COMM_SERVICE_REPLY := 3;
    LOCAL CONST num REPLY_SUCCESS := 1;
    LOCAL CONST num REPLY_FAILURE := 2;
    LOCAL CONST num SEQ_STOP := -4;
    LOCAL VAR socketdev listener;
    LOCAL VAR socketdev client;
    LOCAL VAR rawbytes msg;
    LOCAL VAR num points := 0;

    PROC main()
        VAR iodev cfg;
        VAR num port;
        ros_stop := FALSE;
        Open "HOME:/ros_ports.cfg", cfg \Read;
        port := ReadNum(cfg);
        Close cfg;
        SocketCreate listener;
        SocketBind listener, "127.0.0.1", port;
        SocketListen listener;
        TPWrite "motion server listening";
        SocketAccept listener, client \Time:=WAIT_MAX;
        WHILE TRUE DO
            Receive;
        ENDWHILE
    ERROR
        IF ERRNO = ERR_SOCK_CLOSED THEN
            TPWrite "motion server stopped after points: " \Num:=points;
            ros_stop := TRUE;
            SocketClose client;
            SocketClose listener;
            RETURN;
        ENDIF
        ros_stop := TRUE;
        RAISE;
    ENDPROC

    ! One message: a JOINT_TRAJ_PT is executed (and answered when asked to), others are refused.
    LOCAL PROC Receive()
        VAR num length;
        VAR num msg_type;
        VAR num comm_type;
        VAR num sequence;
        VAR num joint;
        VAR jointtarget target;
        VAR num reply := REPLY_SUCCESS;
        ClearRawBytes msg;
        SocketReceive client \RawData:=msg \ReadNoOfBytes:=68 \Time:=WAIT_MAX;
        UnpackRawBytes msg, 1, length \IntX:=DINT;
        UnpackRawBytes msg, 5, msg_type \IntX:=DINT;
        UnpackRawBytes msg, 9, comm_type \IntX:=DINT;
        UnpackRawBytes msg, 17, sequence \IntX:=DINT;
        IF length <> 64 OR msg_type <> MSG_JOINT_TRAJ_PT THEN
            reply := REPLY_FAILURE;
        ELSEIF sequence = SEQ_STOP THEN
            StopMove;
            ClearPath;
            StartMove;
        ELSE
            target := CJointT();
            UnpackRawBytes msg, 21, joint \Float4;
            target.robax.rax_1 := joint * 180 / pi;
            UnpackRawBytes msg, 25, joint \Float4;
            target.robax.rax_2 := joint * 180 / pi;
            UnpackRawBytes msg, 29, joint \Float4;
            target.robax.rax_3 := joint * 180 / pi;
            UnpackRawBytes msg, 33, joint \Float4;
            target.robax.rax_4 := joint * 180 / pi;
            UnpackRawBytes msg, 37, joint \Float4;
            target.robax.rax_5 := joint * 180 / pi;
            UnpackRawBytes msg, 41, joint \Float4;
            target.robax.rax_6 := joint * 180 / pi;
            MoveAbsJ target, v200, fine, tool0;
            Incr points;
        ENDIF
        IF comm_type = COMM_SERVICE_REQUEST THEN
            PackRawBytes COMM_SERVICE_REPLY, msg, 9 \IntX:=DINT;
            PackRawBytes reply, msg, 13 \IntX:=DINT;
            SocketSend client \RawData:=msg;
        ENDIF
    ENDPROC
ENDMODULE

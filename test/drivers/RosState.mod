MODULE RosState
    ! The state server of a ROS-Industrial robot driver, in a task of its own without a robot:
    ! our own version, written from the published simple_message format (see RosMotion.mod).
    ! Every 50 ms it sends a JOINT_POSITION message (msg_type 10, comm_type 1 = TOPIC,
    ! reply_code 0), 56 bytes after the length: int32 sequence, float32 joint_data[10], the
    ! motion task's robot's axes (CJointT) in radians, unused joints 0. It stops when the motion
    ! server does (ros_stop) or its client goes away.
    ! The port is the second number of HOME:/ros_ports.cfg.
    PERS bool ros_stop := FALSE;
    LOCAL CONST num MSG_JOINT_POSITION := 10;
    LOCAL CONST num COMM_TOPIC := 1;
    LOCAL VAR socketdev listener;
    LOCAL VAR socketdev client;
    LOCAL VAR rawbytes msg;

    PROC main()
        VAR iodev cfg;
        VAR num port;
        VAR num sequence := 0;
        VAR jointtarget joints;
        VAR num axes{10};
        Open "HOME:/ros_ports.cfg", cfg \Read;
        port := ReadNum(cfg);
        port := ReadNum(cfg);
        Close cfg;
        SocketCreate listener;
        SocketBind listener, "127.0.0.1", port;
        SocketListen listener;
        TPWrite "state server listening";
        SocketAccept listener, client \Time:=WAIT_MAX;
        WHILE NOT ros_stop DO
            joints := CJointT();
            axes := [joints.robax.rax_1, joints.robax.rax_2, joints.robax.rax_3, joints.robax.rax_4,
                joints.robax.rax_5, joints.robax.rax_6, 0, 0, 0, 0];
            ClearRawBytes msg;
            PackRawBytes 56, msg, 1 \IntX:=DINT;
            PackRawBytes MSG_JOINT_POSITION, msg, 5 \IntX:=DINT;
            PackRawBytes COMM_TOPIC, msg, 9 \IntX:=DINT;
            PackRawBytes 0, msg, 13 \IntX:=DINT;
            PackRawBytes sequence, msg, 17 \IntX:=DINT;
            FOR i FROM 1 TO 10 DO
                PackRawBytes axes{i} * pi / 180, msg, 17 + 4 * i \Float4;
            ENDFOR
            SocketSend client \RawData:=msg;
            Incr sequence;
            WaitTime 0.05;
        ENDWHILE
        TPWrite "state server stopped";
        SocketClose client;
        SocketClose listener;
    ERROR
        IF ERRNO = ERR_SOCK_CLOSED THEN
            TPWrite "state client went away";
            SocketClose client;
            SocketClose listener;
            RETURN;
        ENDIF
        RAISE;
    ENDPROC
ENDMODULE

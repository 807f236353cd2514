MODULE RosMotion
    ! ROS interface, motion task. Runs in the normal task T_ROB1.
    ! Takes trajectories from the shared buffer and executes them with MoveAbsJ, each
    ! point reached in the time the client asked for. A stop request from the motion
    ! server aborts the current trajectory through a TRAP.

    LOCAL CONST num MIN_DURATION := 0.05;
    ! Joint tolerance in degrees for "already there".
    LOCAL CONST num AT_POINT_TOL := 0.01;
    LOCAL CONST speeddata MAX_SPEED := [2000, 500, 5000, 1000];

    LOCAL VAR RosTrajPoint trajectory{ROS_MAX_POINTS};
    LOCAL VAR num trajectory_size := 0;
    LOCAL VAR intnum stop_int;
    LOCAL VAR bool aborted := FALSE;
    LOCAL VAR num retries := 0;

    PERS tooldata ros_tool := [TRUE, [[0, 0, 0], [1, 0, 0, 0]],
                               [0.001, [0, 0, 0.001], [1, 0, 0, 0], 0, 0, 0]];

    PROC main()
        InitMotion;
        WHILE TRUE DO
            RosTakeBuffer trajectory, trajectory_size;
            IF trajectory_size > 0 THEN
                aborted := FALSE;
                ros_motion_busy := TRUE;
                ExecuteTrajectory;
                ros_motion_busy := FALSE;
            ELSE
                WaitTime 0.01;
            ENDIF
        ENDWHILE
    UNDO
        IDelete stop_int;
        ros_motion_busy := FALSE;
    ENDPROC

    LOCAL PROC InitMotion()
        AccSet 100, 100;
        VelSet 100, MAX_SPEED.v_tcp;
        ConfJ \Off;
        ConfL \Off;
        SingArea \LockAxis4;
        ros_stop_request := FALSE;
        ros_motion_busy := FALSE;
        IDelete stop_int;
        CONNECT stop_int WITH StopTrap;
        IPers ros_stop_request, stop_int;
    ENDPROC

    LOCAL PROC ExecuteTrajectory()
        VAR jointtarget target;
        VAR jointtarget current;
        VAR zonedata zone;
        VAR num duration;

        current := CJointT();
        FOR i FROM 1 TO trajectory_size DO
            IF aborted THEN
                RosTrace "trajectory aborted at point" \Value:=i;
                RETURN;
            ENDIF
            target.robax := trajectory{i}.joints;
            target.extax := trajectory{i}.external;
            duration := trajectory{i}.duration;
            IF i = 1 AND RosJointsNear(target.robax, current.robax, AT_POINT_TOL) THEN
                ! The first point is where the robot stands already.
                CONTINUE;
            ENDIF
            IF i = trajectory_size THEN
                zone := fine;
            ELSE
                zone := z10;                ! blend through the points
            ENDIF
            IF duration < MIN_DURATION THEN
                MoveAbsJ target \NoEOffs, MAX_SPEED, zone, ros_tool;
            ELSE
                MoveAbsJ target \NoEOffs, MAX_SPEED \T:=duration, zone, ros_tool;
            ENDIF
        ENDFOR
    ERROR
        IF ERRNO = ERR_PATH_STOP AND retries < 3 THEN
            Incr retries;
            StartMoveRetry;
        ELSEIF ERRNO = ERR_ROBLIMIT OR ERRNO = ERR_OUTSIDE_REACH THEN
            ErrWrite "ROS motion", "Point out of reach, trajectory dropped";
            retries := 0;
            RETURN;
        ENDIF
        retries := 0;
        RAISE;
    ENDPROC

    ! The motion server set ros_stop_request. IPers fires on every change, so the
    ! trap ignores the change back to FALSE.
    LOCAL TRAP StopTrap
        IF NOT ros_stop_request RETURN;
        aborted := TRUE;
        StopMove \Quick;
        ClearPath;
        StartMove;
        ros_stop_request := FALSE;
        RosTrace "stopped on request";
    ERROR
        IF ERRNO = ERR_PATHDIST THEN
            TRYNEXT;
        ENDIF
    ENDTRAP
ENDMODULE

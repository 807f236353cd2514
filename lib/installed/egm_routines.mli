(** Externally Guided Motion in joint mode (ABB's "Externally Guided Motion" application manual
    and its RAPID pages; egm.sys): EGMGetId, EGMGetState, EGMSetupUC, EGMActJoint, EGMRunJoint,
    EGMStop and EGMReset, for both engines. An EGM process belongs to its task's motion; its
    sensor is a UDP peer on the loopback, named by a UdpUc device of the run (--egm-device;
    {!Rapid_controller.Egm_channel}), that receives EgmRobot messages and answers with EgmSensor
    set points ({!Rapid_controller.Egm_protocol}). EGMRunJoint is a waiting instruction: one
    cycle of the robot's part every activation cycle of virtual time (4 ms unless \SampleRate),
    the arm moving on the run's planner so that CJointT sees it (doc/services.md, "Externally
    Guided Motion"; doc/rulings.md R-13-egm1 to R-13-egm5).

    Not modelled (the call ends the run as an installed routine rapid-sem does not model):
    EGMActPose, EGMRunPose, EGMStreamStart, EGMStreamStop, EGMSetupUC \Pose and \PathCorr,
    EGMActJoint \StreamStart, EGMRunJoint \NoWaitCond. *)

val modelled : string -> bool

val reach : string -> Installed_routine.reach
(** EGMRunJoint reaches the motion; the others the world (the process's UDP channel). *)

val wait_abandoned : Motion_routines.state -> Rapid_controller.World.wait -> unit
(** A wait an error or a long jump leaves (§7.2): if it is EGMRunJoint's, its process is connected
    again, no longer running. *)

val call :
  Primitive.context -> Motion_routines.state -> string -> Primitive.argument array -> Primitive.outcome option
(** The body of one of {!modelled}'s routines; [None] for another name. *)

(** Frames (doc/motion.md, "Frames"): a robtarget is in the work object (uframe · oframe) and is
    reached by the tool's TCP (tframe); the robot's base frame is placed in the world by the cell
    (law F-base) and moved by a track (law X-track): [?base] below. The position
    functions CRobT, CPos, CalcRobT, CalcJointT and CJointT in floats. *)

type robtarget = { pose : Geom.pose; conf : Kinematics.conf }
(** The robot part of a robtarget (its external axes are the planner's: doc/motion.md, "External
    axes"). *)

val object_frame : Motion_data.wobjdata -> Geom.pose
(** uframe · oframe. *)

val flange_of_target :
  Motion_data.tooldata -> Motion_data.wobjdata -> Geom.pose -> (Geom.pose, Motion_error.t) result
(** The flange pose (base frame) that puts the TCP at the target. A robot-held tool and a fixed
    work object: W · target · tframe⁻¹. A stationary tool and a robot-held work object:
    tframe · (W · target)⁻¹. Both or neither held: [Robhold_conflict]. *)

val target_of_flange :
  Motion_data.tooldata -> Motion_data.wobjdata -> Geom.pose -> (Geom.pose, Motion_error.t) result
(** The inverse of [flange_of_target]. *)

val as_robot_held :
  Motion_data.tooldata -> Motion_data.wobjdata ->
  (Motion_data.tooldata * Motion_data.wobjdata * (Geom.pose -> Geom.pose)) option
(** A stationary tool (robhold FALSE) and a robot-held work object as the same flange poses
    with a robot-held tool and a fixed work object: the work object's frame (uframe · oframe,
    from the flange) as the tool, wobj0, and a target's pose T as tframe · T⁻¹ in the world.
    [None] for any other pair. *)

val calc_rob_t :
  ?base:Geom.pose -> Kinematics.t -> float array -> Motion_data.tooldata -> Motion_data.wobjdata ->
  (robtarget, Motion_error.t) result
(** CalcRobT(Joint_target, Tool [\WObj]): the robtarget of axis angles, with their confdata. *)

val calc_joint_t :
  ?base:Geom.pose -> Kinematics.t -> robtarget -> Motion_data.tooldata -> Motion_data.wobjdata ->
  (float array, Motion_error.t) result
(** CalcJointT(Rob_target, Tool [\WObj]): the axis angles with the robtarget's confdata; an
    error carries ERR_ROBLIMIT for \ErrorNumber ({!Motion_error.errnum}). *)

val c_rob_t :
  ?base:Geom.pose -> Kinematics.t -> joints:float array -> Motion_data.tooldata -> Motion_data.wobjdata ->
  (robtarget, Motion_error.t) result
(** CRobT([\Tool] [\WObj]) given the current axis angles (CJointT, from the planner). *)

val c_pos :
  ?base:Geom.pose -> Kinematics.t -> joints:float array -> Motion_data.tooldata -> Motion_data.wobjdata ->
  (Geom.pos, Motion_error.t) result
(** CPos([\Tool] [\WObj]): the translation of CRobT.

    [?base] (all four): the robot's base in the world ({!Planner.base}: the cell's base frame,
    law F-base, moved by a track, law X-track); the world frame by default. *)

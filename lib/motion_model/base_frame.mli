(** A robot's base frame (doc/motion.md, "Frames", law F-base): where the cell mounts the arm, a
    pose in the world frame. ABB's system parameters give it for each robot (topic Motion, type
    Robot, "Base Frame" x, y, z in metres and q1 to q4; MOC.cfg's [-base_frame_pos_x] ...
    [-base_frame_orient_u3]); robtargets in wobj0 are in the world frame, so a target is brought
    into the base frame before the inverse kinematics, and CRobT, CPos, CalcRobT answer through
    it. Only the kinematics sees it: the model has no gravity. *)

val is_world : Geom.pose -> bool
(** The world frame itself (a robot standing at the world's origin, upright). *)

val in_world : Robot.t -> float array -> Geom.pose option
(** The robot's base in the world at these extjoint components: the tracks' translation (law
    X-track) times the cell's base frame ({!Robot.t.base_frame}, given at the track's 0); [None]
    when neither moves it from the world frame. *)

val max_offset : float
(** 1E7 mm (10 km): the farthest a base frame's origin may be from the world's, a bound that
    keeps every position the kinematics computes finite. *)

val orientation : float -> float -> float -> float -> (Geom.orient, string) result
(** The quaternion q1 q2 q3 q4 of a base frame, normalised and with q1 >= 0 (q and -q are one
    orientation): its norm must be within 0.001 of 1 (the six digits MOC.cfg writes, 0.707107,
    are); otherwise, or with a component that is not finite, why not. *)

val position : float -> float -> float -> (Geom.pos, string) result
(** The origin in mm: each coordinate finite and within {!max_offset}; otherwise why not. *)

val of_text : string -> (Geom.pose, string) result
(** [X,Y,Z,Q1,Q2,Q3,Q4] as --base-frame takes it (doc/user-guide.md): the origin in mm and the
    quaternion, seven decimal numbers separated by commas (blanks around them allowed). *)

val to_text : Geom.pose -> string
(** The pose as [of_text] reads it, each number with up to nine significant digits. *)

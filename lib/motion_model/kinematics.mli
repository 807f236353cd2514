(** Forward and inverse kinematics of a {!Robot.t}, with ABB's confdata (doc/motion.md,
    "Kinematics"). Angles are in degrees, lengths in mm; poses are of the flange (tool0) in the
    robot's base frame. *)

type conf = { cf1 : int; cf4 : int; cf6 : int; cfx : int }
(** confdata: the quadrants of axes 1, 4 and 6 (quadrant n covers [n·90°, (n+1)·90°)) and the
    configuration number cfx (installed-facts.md §3, cf1/cf4/cf6 CORROBORATED). cfx is
    4·(wrist centre behind axis 1) + 2·(wrist centre behind the lower arm) + (axis 5 negative),
    ABB's table order; its bit assignment is UNCERTAIN (installed-facts.md §3). *)

type error = Motion_error.t

type t
(** A robot with the workspace its forward kinematics computes in (GSL matrices, reused: not for
    use by two threads at once). *)

val create : Robot.t -> t
val robot : t -> Robot.t

val forward : t -> float array -> Geom.pose
(** The flange pose of six axis angles: the product of the six DH transforms (GSL dgemm). *)

val conf_of : t -> float array -> conf
(** The confdata of six axis angles. *)

val wrist_singular : ?zone:float -> t -> float array -> bool
(** Axis 4 and 6 aligned: |sin theta5| below [sin zone] ([zone] in degrees, default
    {!singular_zone}). *)

val singular_zone : float
(** 1 degree: the half-width of the wrist singularity zone in which SingArea \Off refuses a
    linear or circular move (doc/motion.md, "R-motion-singarea"). *)

val significant : t -> conf -> conf
(** The part of a confdata that names a solution of this arm: all of it, but for a palletiser
    (doc/motion.md R-structure) cf4 and cfx's axis 5 bit are 0. *)

type choice =
  | With_conf of conf  (** the solution the confdata names: MoveJ, CalcJointT *)
  | Nearest of float array  (** the solution nearest these axis angles: ConfL \Off, the path *)

val inverse : t -> Geom.pose -> choice -> (float array, error) result
(** The axis angles that put the flange at the pose. A wrist singularity is solved (axis 4 kept
    at the reference, or at its quadrant's middle) and is not an error here: SingArea is the
    planner's. *)

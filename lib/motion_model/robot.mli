(** The robot description: a six-axis arm given by its Denavit–Hartenberg parameters, axis
    ranges and axis speeds, in a small text format (doc/motion.md, "The robot description"), so
    that a robot other than the built-in default can be given on the command line
    ([--robot FILE], to come). *)

type axis = {
  a : float;  (** DH link length, mm *)
  alpha : float;  (** DH link twist, degrees *)
  d : float;  (** DH link offset, mm *)
  offset : float;  (** DH joint angle at axis angle 0, degrees: theta = angle + offset *)
  min : float;  (** lower axis limit, degrees *)
  max : float;  (** upper axis limit, degrees *)
  speed : float;  (** maximum axis speed, degrees/s *)
}

type structure =
  | Serial  (** each axis angle measured against the link before it (the default) *)
  | Coupled_axis3
      (** axis 3's angle is the upper arm's against the horizontal, not against the lower arm, so
          that axis 2 alone moves the lower arm and leaves the upper arm's attitude: the arms whose
          axis 3 drive works through a parallel rod (IRB 1600, 2400, 6700, 7600; doc/rulings.md
          R-structure); the DH chain's joint 3 is axis 3 minus axis 2 *)
  | Palletiser
      (** four axes, 1, 2, 3 and 6: a lower arm (axis 2, from the vertical), an upper arm kept by a
          parallel rod (axis 3, its attitude against the horizontal, positive down) and a flange
          kept level, pointing down, turned by axis 6 (IRB 660). The columns: axis 1 [a] and [d]
          place axis 2 ahead of and above the base, axis 2 [a] the lower arm, axis 3 [a] the upper
          arm, axis 6 [a] and [d] the flange ahead of and below the upper arm's end; twists and
          offsets are 0. Axes 4 and 5 are not given and stand at 0. *)
  | Delta
      (** four axes, 1 to 4 (IRB 360): three upper arms at 0, 120 and 240 degrees about the base's
          z, each turned by its axis (0 level, positive down), with parallel rods to a plate kept
          level; axis 4 turns the flange about its z. Axes 1 to 3 [a]: the upper arm, [d]: the
          rod (the same for all three); axis 4 [a]: the base's radius less the plate's, [d]: the
          flange below the plate. Axes 5 and 6 are not given and stand at 0. *)
  | Scara
      (** four axes, 1 to 4 (IRB 910SC): axis 1 turns the inner arm and axis 2 the outer arm about
          vertical axes (0: in line along the base's x), axis 3 moves the quill along z (mm,
          positive up; its speed in mm/s) and axis 4 turns the flange, which points down, about
          its z. Axis 1 [a]: the inner arm, [d]: the flange's height above the base at axis 3 =
          0; axis 2 [a]: the outer arm; the other lengths, twists and offsets 0. Axes 5 and 6 are
          not given and stand at 0 (doc/rulings.md R-structure-scara). *)

type t = {
  name : string;
  structure : structure;  (** [structure serial|coupled-axis3|palletiser|delta|scara] *)
  axes : axis array;  (** six axes, axis 1 first *)
  max_tcp_speed : float;  (** mm/s: vmax's v_tcp and MaxRobSpeed() *)
  externals : Ext_axes.axis list;  (** external axes, in the order of the description; none by default *)
  reach : float option;
      (** mm: the reach of the wrist centre its product specification gives, where the description
          states it (informative: the library's tests compare the kinematics with it) *)
  base_frame : Geom.pose;
      (** where the cell mounts the arm: its base frame in the world frame (mm, quaternion), at
          the track's 0 when a track carries it ({!Base_frame}). The cell's, not the arm's: a
          description never sets it ({!parse} gives the world frame); a backup's MOC.cfg (ROBOT's
          base_frame attributes) or --base-frame does (doc/rulings.md R-bk-12) *)
}

val irb120 : t
(** The default robot: ABB IRB 120 with the dimensions, ranges and speeds of installed-facts.md
    §3 "A default robot for the kinematic model". *)

val irb120_text : string
(** The same robot as a description file: the format's reference example. *)

type error = { file : string; line : int; col : int; message : string }

val error_to_string : error -> string
(** [FILE:LINE:COL: robot description error: MESSAGE]. *)

val parse : file:string -> string -> (t, error) result
(** Reads a description. Refuses what the model cannot move: a missing or repeated axis, an
    empty or inverted range, a speed that is not positive, a number that is not decimal or is
    beyond num or the model's ranges (doc/rulings.md R-2.13-numbers2), and a kinematic structure
    other than the one the analytic inverse kinematics solves (see {!Kinematics}). *)

val load : string -> (t, error) result
(** [parse] of a file's contents; an unreadable file is an error at 1:1. *)

val present : t -> int -> bool
(** Whether the arm has axis [k] (1 to 6): a palletiser has no axes 4 and 5, a delta and a SCARA
    no 5 and 6. *)

val structure_error : t -> string option
(** Why the analytic inverse kinematics cannot solve this arm, or [None]. *)

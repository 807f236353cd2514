(** External axes (doc/motion.md, "External axes"): up to six axes beside the arm, eax_a to
    eax_f as extjoint names them (a robtarget's and a jointtarget's [extax]), each linear (mm,
    mm/s) or rotating (degrees, degrees/s). A linear axis may be a track carrying the robot: the
    robot's base then moves along a direction of the world frame with it (law X-track). *)

type kind = Linear | Rotating

type axis = {
  name : string;  (** eax_a … eax_f *)
  index : int;  (** 0 for eax_a … 5 for eax_f: its component of extjoint *)
  kind : kind;
  min : float;  (** lower limit, mm or degrees *)
  max : float;  (** upper limit *)
  speed : float;  (** maximum speed, mm/s or degrees/s *)
  track : Geom.pos option;  (** a track carrying the robot: the unit direction it moves the base along, world frame *)
}

val names : string array
(** [| "eax_a"; …; "eax_f" |]. *)

val unused : float
(** 9E9 as a num holds it (single precision, 8999999488): ABB's "axis not used". *)

val is_unused : float -> bool
(** A component of 9E9 or more: the axis is not used (R-4.1-w). *)

val initial : axis list -> float array
(** The six components where the robot starts: 0 (or the range's nearer end when 0 is outside
    it) for the described axes, 9E9 for the others. *)

val resolve : axis list -> from:float array -> float array -> (float array, Motion_error.t) result
(** The six components a move ends at, from where they are ([from]) and the programmed ones
    (law X-target): a described axis given 9E9 keeps its position; a component for an axis the
    robot does not have is ignored (9E9); a described axis beyond its range, or not a number, is
    [External_out_of_range]. *)

val base : axis list -> float array -> Geom.pose option
(** The robot's base in the world at these components (law X-track): the translation of the
    tracks' positions along their directions; [None] when the robot stands on no track (the base
    frame is the world frame). *)

val time : axis list -> override:float -> v_leax:float -> v_reax:float -> from:float array ->
  float array -> (float, Motion_error.t) result
(** Law X-time: the longest of the described axes' |Δe| / min(v · Override/100, axis speed),
    v being v_leax for a linear axis and v_reax for a rotating one; 0 when none moves. *)

(** The motion planner (doc/motion.md, "The program pointer and the motion pointer"): the motion
    queue of one robot on virtual time. A move instruction hands its segment to [plan], which says
    when the program may go on ([ready_time]: for a fly-by point the look-ahead horizon before the
    robot can enter its zone, or at once if that has passed; for a stop point when the robot
    stands in position there). [pose_at] and [joints_at] say where the
    robot is at any time, between programmed points too. Times are seconds of the machine's
    virtual clock, which only moves forward. *)

type motion =
  | Linear of Frames.robtarget  (** MoveL ToPoint *)
  | Circular of Frames.robtarget * Frames.robtarget  (** MoveC CirPoint ToPoint *)
  | Joint of Frames.robtarget  (** MoveJ ToPoint *)
  | Abs_joint of float array  (** MoveAbsJ ToJointPos: axis angles, degrees *)
  | External_only  (** MoveExtJ: the external axes move, the arm's axes stay (law X-extj) *)

type move = {
  motion : motion;
  timing : Profile.timing;  (** Speed [\V] [\T] *)
  zone : Motion_data.zonedata;  (** Zone *)
  z : float option;  (** \Z: replaces pzone_tcp *)
  inpos : Motion_data.stoppointdata option;  (** \Inpos: a stop point with these criteria *)
  conc : bool;  (** \Conc *)
  tool : Motion_data.tooldata;
  wobj : Motion_data.wobjdata;  (** \WObj, wobj0 when absent *)
  label : string;  (** the target's name, for output *)
  eax : float array;
      (** the target's extjoint, eax_a … eax_f (9E9: not used; law X-target); MoveC: ToPoint's *)
}

val move :
  ?v:float -> ?t:float -> ?z:float -> ?inpos:Motion_data.stoppointdata -> ?conc:bool ->
  ?tool:Motion_data.tooldata -> ?wobj:Motion_data.wobjdata -> ?label:string -> ?eax:float array ->
  Motion_data.speeddata -> Motion_data.zonedata -> motion -> move
(** A move with tool0, wobj0, no external axis used (all 9E9) and no optional argument unless
    given. *)

type settings = {
  mutable velset : Profile.velset;  (** VelSet *)
  mutable conf_l : bool;  (** ConfL \On (default) / \Off *)
  mutable conf_j : bool;  (** ConfJ \On (default) / \Off *)
  mutable sing_area_wrist : bool;  (** SingArea \Wrist / \Off (default) *)
  mutable look_ahead : float;
      (** how long before a fly-by point's zone the program pointer may leave its move, s
          (default 0.1: ABB's planning time DT, installed-facts.md §5, CONFIRMED as approximate) *)
  mutable speed_limit : Profile.speed_limit option;
      (** the limits of SpeedLimCheckPoint and SpeedLimAxis while the system input LimitSpeed is
          active, for the moves planned now; [None]: not active *)
}

type warning =
  | Corner_path_failure of int
      (** the segment's fly-by point became a stop point: the next move came after its corner
          had to begin (ABB event "corner path failure") *)

type planned = { id : int; ready_time : float; warnings : warning list }

type t

val create : ?joints:float array -> Kinematics.t -> t
(** An empty queue with the robot standing at [joints] (default all 0) from time 0. *)

val settings : t -> settings
val kinematics : t -> Kinematics.t

val plan : t -> now:float -> move -> (planned, Motion_error.t) result
(** Hands a move to the planner at time [now]. An error leaves the queue as it was. *)

val ready_time : t -> int -> float
(** When the program may leave the move with this id, in the light of StopMove and StartMove
    since it was planned; [infinity] while the robot is stopped short of it. For a move of a path
    level dropped by RestoPath, the time [plan] answered. Raises [Invalid_argument] for an id
    [plan] did not give. *)

val pose_at : t -> float -> Geom.pose
(** The TCP pose (world frame, tool of the move under way) at a time. *)

val joints_at : t -> float -> (float array, Motion_error.t) result
(** The arm's six axis angles at a time (CJointT); an error where a linear path leaves the
    workspace. *)

val external_at : t -> float -> (float array, Motion_error.t) result
(** The six extjoint components at a time (CJointT, CRobT): where the described external axes
    are, 9E9 for the others. *)

val base : t -> float array -> Geom.pose option
(** The robot's base in the world at these extjoint components, when the cell's base frame or a
    track moves it from the world frame ({!Base_frame.in_world}). *)

val finished_by : t -> float
(** When the robot will stand still at the end of all it has been given ([infinity] while
    stopped with motion left). *)

val stop : t -> at:float -> unit
(** StopMove: the robot stands still at once from [at]; the path is kept. *)

val start : t -> at:float -> unit
(** StartMove: the path goes on from where it stopped, from [at]. *)

val stopped : t -> bool

val clear : t -> at:float -> unit
(** ClearPath: everything not done at [at] is dropped; the robot stands where it is and the next
    move starts from there. *)

val path_level : t -> int
(** PathLevel(): 1, or 2 between StorePath and RestoPath. *)

val store_path : t -> at:float -> (unit, Motion_error.t) result
(** StorePath: the path of level 1 is stopped at [at] (if it is not already) and kept; level 2
    begins, empty, with the robot where it stands. On level 2 already: an error. *)

val resto_path : t -> at:float -> (unit, Motion_error.t) result
(** RestoPath: level 2 is dropped and level 1 comes back, still stopped: StartMove resumes it
    from where it stopped (the program is to have moved the robot back there). On level 1: an
    error. *)

(** {1 The planned path, for output} *)

type piece_kind = Segment of int | Corner of int * int | Still

type piece_info = { t_from : float; t_to : float; kind : piece_kind }

val pieces : t -> piece_info list
(** The timed pieces of the path, in time order (real time). *)

type segment_info = {
  seg_id : int; seg_label : string; seg_kind : string;  (** "MoveL", "MoveC", "MoveJ", "MoveAbsJ" *)
  target : Geom.pos;  (** the programmed point's TCP position, world frame *)
  seg_fine : bool; seg_length : float; seg_duration : float;
}

val segments : t -> segment_info list

(** {1 For the machine's events} *)

val target_joints : t -> int -> float array
(** The arm's axis angles at the programmed point of the move with this id. *)

val target_external : t -> int -> float array
(** The extjoint components at the programmed point of the move with this id. *)

val segment_span : t -> int -> (float * float) option
(** When the move's motion begins (its incoming corner, or its own part) and ends (where its
    outgoing corner begins, or at its point), real time, on the current path level; [None] for a
    move not (or no longer) in the queue. Cheap for recent moves. *)

val has_segment : t -> int -> bool
(** [segment_span t id <> None], without computing the span. *)

val segment_spans : t -> int list -> int -> (float * float) option
(** [segment_spans t ids] answers [segment_span t id] for every [id] of [ids], walking the
    queue once. *)

val point_time : t -> int -> float option
(** When the robot passes the move's programmed point: the middle of its corner path (MoveLDO,
    MoveJDO), or the end of its part; [None] when not in the queue. *)

val forget : t -> before:float -> keep:int -> unit
(** A run that keeps no history (doc/motion.md, "Memory") gives back what it no longer needs:
    the pieces of path wholly before time [before] that concern only moves older than [keep], and
    the moves older than [keep] whose ready time has passed by [before]. Afterwards [pose_at],
    [joints_at] and [external_at] answer for times from [before] on only, [target_joints] and
    [target_external] for moves from [keep] on, and [ready_time] of a forgotten move is a time
    not after [before]. [pieces] and [segments] then list what is kept. *)

val is_open : t -> int -> bool
(** Whether the move is the last one, ending in a fly-by point whose corner waits for the next
    move. *)

(** {1 Triggers on the path (TriggL, TriggJ, TriggC; doc/motion.md, law T-distance)} *)

val time_at_distance : ?from_end:bool -> ?shift:float -> t -> int -> float -> float option
(** [time_at_distance t id d]: when the TCP of the move [id] has gone [d] mm along its segment
    from the segment's start (with [from_end], when it is [d] mm before the segment's end), by
    the segment's own time law (s = d / L at constant speed, inside the corner paths too, which
    take the time of the parts they replace), clamped to the segment, plus [shift] seconds of
    path time, and never before the move's motion begins: a real time in the light of StopMove
    and StartMove, [infinity] while the robot is stopped short of it; [None] when the path has
    been dropped before it. ABB's triggers measure the distance from the move's start or end
    point (TriggIO, TriggInt: RAPID Instructions); a TCP that does not move (L = 0) is at the
    start for 0 from the start and at the end for any other distance. Raises
    [Invalid_argument] for a move forgotten or not planned. *)

type mark
(** A moment of the path that a trigger waits for: it follows StopMove and StartMove, and is
    dropped with the path (ClearPath, RestoPath) when the robot has not got to it. *)

val mark : ?from_end:bool -> ?shift:float -> t -> int -> float -> mark
(** The moment of {!time_at_distance}, kept until {!release}, so that it can be asked for after
    the move is forgotten. *)

val mark_time : t -> mark -> float option
(** As {!time_at_distance} answers for the mark, now. *)

val release : t -> mark -> unit

val segment_length : t -> int -> float
(** The TCP path length of the move's segment, mm (law L-sum; MoveJ: the chord). *)

val segment_speed : t -> int -> float
(** The move's TCP speed, length over time, mm/s (0 for a move of no time). *)

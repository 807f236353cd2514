(** What the motion of a run makes observable (doc/motion.md, doc/trace-format.md), each with its
    virtual time (seconds). *)

type t =
  | Segment_planned of {
      time : float;                      (** when the move instruction ran *)
      id : int;
      instruction : string;              (** MoveL, MoveJ, MoveC, MoveAbsJ, MoveLDO, MoveJDO, SearchL *)
      label : string;                    (** the target's data object, or [*] *)
      zone : string;                     (** [fine], or the zonedata's object, or [*] *)
      target : Pose.t;                   (** the programmed TCP pose, world frame *)
      joints : float array;              (** the axis angles there, degrees *)
      ready_time : float;                (** when the program pointer may go on *)
      start_time : float;                (** when the robot begins the move, as planned now *)
      end_time : float;                  (** when it leaves it (the corner's start for a fly-by) *)
    }
  | Segment_started of { time : float; id : int; label : string }
  | Segment_ended of { time : float; id : int; label : string }
  | Segment_dropped of { time : float; id : int; label : string }  (** ClearPath *)
  | Path_command of { time : float; command : string }
      (** StopMove, StartMove, ClearPath, StorePath, RestoPath, ProcerrRecovery, collision,
          SearchL stop *)
  | Motion_warning of { time : float; text : string }  (** corner path failure *)

val to_string : t -> string
(** One line, for the trace and test messages. *)

val time : t -> float
